/**
 * \file
 * \brief VISCA focus and iris: Sony's CAM_Focus, CAM_Iris and CAM_AE packets, and how a camera's lens numbers map to
 * the node's shares (doc/backends/visca.md).
 */
#pragma once

#include <cstdint>
#include <vector>

#include "ptz_action_server/core/lens.h"
#include "ptz_action_server/core/visca/visca_codec.h"

namespace ptz_action_server
{
namespace visca
{
/// What a camera's lens takes: whether it has focus and iris, and its position numbers at each end of their ranges.
struct ViscaLens
{
  bool focus = true;
  bool iris = true;
  std::uint16_t focus_near = 0xF000;  ///< CAM_Focus direct at the near end (Sony FCB and SRG tables)
  std::uint16_t focus_far = 0x1000;   ///< at the far end (infinity)
  std::uint8_t iris_closed = 0x00;    ///< CAM_Iris direct fully closed
  std::uint8_t iris_open = 0x11;      ///< fully open (F1.6 on Sony's FCB-EV7500)
  /// s between two lens inquiries (one a poll round at most, in turn: focus mode, focus position, iris position);
  /// 0: the lens is not polled (lens_state then shows the modes the node sent).
  double poll_period = 0.2;

  /// Shares (see lens.h) <-> the camera's numbers, clamped to the range.
  std::uint16_t focusPosition(double share) const;
  double focusShare(std::uint16_t position) const;
  std::uint8_t irisPosition(double share) const;
  double irisShare(std::uint8_t position) const;
  /// What this lens declares: focus auto/manual, near/far, direct, one-push; iris auto (CAM_AE full auto) or manual
  /// (iris priority) and direct, no drive (CAM_Iris up/down are single steps). Feedback where \p focus_polled
  /// (\p iris_polled): the position is asked in the poll round.
  LensCapabilities capabilities(bool focus_polled = false, bool iris_polled = false) const;
};

Packet focusMode(std::uint8_t address, bool automatic);  ///< `8x 01 04 38 02 FF` (auto) / `03` (manual)
Packet focusOnePush(std::uint8_t address);               ///< `8x 01 04 18 01 FF`
/// `8x 01 04 08 00 FF` (stop, speed 0), far `2p`, near `3p` with p = |speed| - 1 (speed -8..8, positive far).
Packet focusDrive(std::uint8_t address, int speed);
Packet focusDirect(std::uint8_t address, std::uint16_t position);  ///< `8x 01 04 48 0p 0q 0r 0s FF`
/// The exposure mode: `8x 01 04 39 00 FF` (full auto: automatic iris) or `0B` (iris priority: the iris as set).
Packet irisMode(std::uint8_t address, bool automatic);
Packet irisDirect(std::uint8_t address, std::uint8_t position);  ///< `8x 01 04 4B 00 00 0p 0q FF`
Packet focusModeInquiry(std::uint8_t address);                   ///< CAM_FocusModeInq `8x 09 04 38 FF`
Packet focusPositionInquiry(std::uint8_t address);               ///< CAM_FocusPosInq `8x 09 04 48 FF`
Packet irisPositionInquiry(std::uint8_t address);                ///< CAM_IrisPosInq `8x 09 04 4B FF`
/// CAM_FocusModeInq's answer `y0 50 02 FF` (auto) / `03` (manual; `04`, one-push mode on some non-Sony cameras, is
/// manual too). False for any other answer.
bool decodeFocusModeAnswer(const Reply& reply, LensMode& mode);
/// CAM_FocusPosInq's answer `y0 50 0p 0q 0r 0s FF`.
bool decodeFocusPositionAnswer(const Reply& reply, std::uint16_t& position);
/// CAM_IrisPosInq's answer `y0 50 00 00 0p 0q FF`.
bool decodeIrisPositionAnswer(const Reply& reply, std::uint8_t& position);

/// The share -1..1 of the top focus speed as a drive speed -8..8 (0 stays 0; any other share at least 1).
int focusSpeed(double share);

/**
 * \brief The packets of \p command for a camera whose lens was last in \p state: a focus (iris) command other than
 * a mode, to a function not known to be manual, switches it to manual first (a Sony camera refuses a manual focus
 * command, one-push included, during auto focus). Empty where \p lens lacks it (the node checked before).
 */
std::vector<Packet> lensPackets(std::uint8_t address, const ViscaLens& lens, const LensCommand& command,
                                const LensState& state);

}  // namespace visca
}  // namespace ptz_action_server
