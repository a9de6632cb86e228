/**
 * \file
 * \brief The VISCA model presets, from their makers' command tables. doc/backends/visca.md gives the source of every
 * figure, and says which were not found (those are conservative guesses, marked "not found" below).
 */
#include <functional>
#include <utility>

#include "ptz_action_server/core/visca/visca_model.h"

namespace ptz_action_server
{
namespace visca
{
namespace
{
constexpr std::uint16_t SONY = 0x0001;

/// Sony's "speed step normal" table of the ILME-FR7 and BRC-AM7 (deg/s of 01h..18h).
const std::vector<double> SONY_NORMAL_SPEEDS = { 0.05, 0.1, 0.2, 0.4,  0.5,  0.8,  1.1,  1.4,  1.9,  2.5,  3.2,  4.0,
                                                 5.1,  6.4, 8.0, 10.0, 12.5, 15.5, 19.6, 24.2, 30.1, 37.8, 47.1, 60.0 };

ViscaAxis axis(double steps_per_degree, double min_degrees, double max_degrees, std::uint8_t max_speed_byte,
               double max_speed, std::vector<double> speed_table = {}, bool reversed = false)
{
  return ViscaAxis{ steps_per_degree,       min_degrees, max_degrees, max_speed_byte, max_speed,
                    std::move(speed_table), reversed };
}

/// The last row of \p table: its fastest byte and speed.
ViscaAxis tableAxis(double steps_per_degree, double min_degrees, double max_degrees, const std::vector<double>& table,
                    bool reversed = false)
{
  return axis(steps_per_degree, min_degrees, max_degrees, static_cast<std::uint8_t>(table.size()), table.back(), table,
              reversed);
}

ViscaModel eviD70()
{
  // EVI-D70 technical manual: pan F725h..08DBh = -170..+170 degrees, tilt FE70h..04B0h = -30..+90 (0.075 degrees a
  // step); pan speed bytes 01..18h up to 100 deg/s, tilt 01..17h up to 90 deg/s; optical zoom 0000h..4000h, 18x.
  ViscaModel model;
  model.axes = { { axis(13.3333, -170.0, 170.0, 0x18, 100.0), axis(13.3333, -30.0, 90.0, 0x17, 90.0) } };
  model.zoom_table = { { 0x0000, 1.0 }, { 0x4000, 18.0 } };
  model.vendor_id = SONY;
  return model;
}

ViscaModel eviD30()
{
  // EVI-D30/D31: pan FC90h..0370h = -100..+100 degrees, tilt FED4h..012Ch = -25..+25; pan bytes 01..18h at 3.3
  // deg/s each (80), tilt 01..14h at 2.5 each (50); zoom 0000h..03FFh, 12x.
  ViscaModel model;
  model.axes = { { axis(8.8, -100.0, 100.0, 0x18, 80.0), axis(12.0, -25.0, 25.0, 0x14, 50.0) } };
  model.zoom_table = { { 0x0000, 1.0 }, { 0x03FF, 12.0 } };
  model.vendor_id = SONY;
  return model;
}

ViscaModel ptzOptics()
{
  // PTZOptics G2 and G3 (raw VISCA and VISCA over IP): 14.4 steps a degree, pan +-2448 = +-170 degrees, tilt
  // -432..+1296 = -30..+90; pan bytes 01..18h, tilt 01..14h; zoom 0000h..4000h. The deg/s of the top bytes and the
  // X-factor of 4000h (12x, 20x or 30x by model) are not in PTZOptics' VISCA list: nominal 100 / 70 deg/s and 20x.
  ViscaModel model;
  model.axes = { { axis(14.4, -170.0, 170.0, 0x18, 100.0), axis(14.4, -30.0, 90.0, 0x14, 70.0) } };
  model.zoom_table = { { 0x0000, 1.0 }, { 0x4000, 20.0 } };
  return model;
}

ViscaModel brcX1000(std::uint16_t model_id)
{
  // BRC-X1000/H800/H780 command list: pan as 5 nibbles, tilt as 4 (`8x 01 06 02 vv ww 0p 0p 0p 0p 0p 0t 0t 0t 0t FF`,
  // answer `y0 50 0p*5 0t*4 FF`, 12 bytes); 10 degrees = 00937h (235.9 steps a degree), pan +-170 (09CA7h), tilt
  // -30 (E45Bh)..+90 (52EFh); the table lists the positive pan counts under "Left". Drive bytes 01..18h on both axes;
  // their deg/s are not in the table (not found: 60 deg/s at 18h, Sony's figure for the FR7/AM7/360SHE). Zoom
  // 0000h..4000h = 1..12x optical, the table's rows.
  ViscaModel model;
  model.axes = { { axis(235.9, -170.0, 170.0, 0x18, 60.0, {}, true), axis(235.9, -30.0, 90.0, 0x18, 60.0) } };
  model.layout = PositionLayout{ 5, 4, false };
  model.zoom_table = { { 0x0000, 1.0 }, { 0x1800, 2.0 },  { 0x2340, 3.0 },  { 0x2A40, 4.0 },
                       { 0x2F00, 5.0 }, { 0x3300, 6.0 },  { 0x3600, 7.0 },  { 0x3880, 8.0 },
                       { 0x3AC0, 9.0 }, { 0x3CC0, 10.0 }, { 0x3E80, 11.0 }, { 0x4000, 12.0 } };
  model.vendor_id = SONY;
  model.model_id = model_id;
  return model;
}

ViscaModel brcX400()
{
  // BRC-X400/X401 (SRG-X400 family) command list: 4 + 4 nibbles, one speed (`8x 01 06 02 vv 00 ..`); pan DE00h..2200h
  // = -170..+170 (51.2 steps a degree), tilt FC00h (-20)..1200h (+90), image flip off. Speeds "slow off": pan
  // 01..18h, tilt 01..17h (the tables below). Zoom 0000h..4000h = 1..20x optical.
  const std::vector<double> pan = { 1.1, 1.3, 1.6, 2.2, 2.9, 6.7, 11, 23, 24, 27, 41, 43,
                                    47,  49,  54,  57,  62,  64,  69, 72, 80, 84, 91, 101 };
  const std::vector<double> tilt(pan.begin(), pan.end() - 1);
  ViscaModel model;
  model.axes = { { tableAxis(51.2, -170.0, 170.0, pan), tableAxis(51.2, -20.0, 90.0, tilt) } };
  model.layout = PositionLayout{ 4, 4, true };
  model.zoom_table = { { 0x0000, 1.0 },  { 0x0DC1, 2.0 },  { 0x186C, 3.0 },  { 0x2015, 4.0 },  { 0x2594, 5.0 },
                       { 0x29B7, 6.0 },  { 0x2CFB, 7.0 },  { 0x2FB0, 8.0 },  { 0x320C, 9.0 },  { 0x342D, 10.0 },
                       { 0x3608, 11.0 }, { 0x37AA, 12.0 }, { 0x391C, 13.0 }, { 0x3A66, 14.0 }, { 0x3B90, 15.0 },
                       { 0x3C9C, 16.0 }, { 0x3D91, 17.0 }, { 0x3E72, 18.0 }, { 0x3F40, 19.0 }, { 0x4000, 20.0 } };
  model.vendor_id = SONY;
  model.model_id = 0x051C;
  return model;
}

ViscaModel srg360she()
{
  // SRG-360SHE command list: 5 + 5 nibbles and one speed (`8x 01 06 02 VV 00 0Y*5 0Z*5 FF`); pan EAC00h..15400h =
  // -170..+170 (512 steps a degree), tilt FC400h (-30)..0B400h (+90), flip off. Speeds 01..18h, slow mode off (the
  // tables below). Zoom 0000h..4000h = 1..30x optical.
  const std::vector<double> pan = { 0.3, 0.4, 0.5, 0.6, 0.7, 0.9, 1.2, 1.5, 1.9, 2.4, 3.0, 3.6,
                                    4.2, 6.6, 7.8, 8.9, 13,  16,  20,  24,  30,  38,  47,  60 };
  const std::vector<double> tilt = { 0.3, 0.4, 0.5, 0.6, 0.7, 0.9, 1.2, 1.5, 1.9, 2.4, 3.0, 3.8,
                                     4.7, 5.9, 7.5, 8.9, 12,  15,  19,  24,  30,  38,  47,  60 };
  ViscaModel model;
  model.axes = { { tableAxis(512.0, -170.0, 170.0, pan), tableAxis(512.0, -30.0, 90.0, tilt) } };
  model.layout = PositionLayout{ 5, 5, true };
  model.zoom_table = { { 0x0000, 1.0 },  { 0x16A1, 2.0 },  { 0x2063, 3.0 },  { 0x2628, 4.0 },  { 0x2A1D, 5.0 },
                       { 0x2D13, 6.0 },  { 0x2F6D, 7.0 },  { 0x3161, 8.0 },  { 0x330D, 9.0 },  { 0x3486, 10.0 },
                       { 0x35D7, 11.0 }, { 0x3709, 12.0 }, { 0x3820, 13.0 }, { 0x3920, 14.0 }, { 0x3A0A, 15.0 },
                       { 0x3ADD, 16.0 }, { 0x3B9C, 17.0 }, { 0x3C46, 18.0 }, { 0x3CDC, 19.0 }, { 0x3D60, 20.0 },
                       { 0x3DD4, 21.0 }, { 0x3E39, 22.0 }, { 0x3E90, 23.0 }, { 0x3EDC, 24.0 }, { 0x3F1E, 25.0 },
                       { 0x3F57, 26.0 }, { 0x3F8A, 27.0 }, { 0x3FB6, 28.0 }, { 0x3FDC, 29.0 }, { 0x4000, 30.0 } };
  model.vendor_id = SONY;
  model.model_id = 0x0604;
  return model;
}

/// A camera whose lens decides the X-factor of its zoom positions: 0000h is the wide end, 4000h the optical tele end.
void lensDependentZoom(ViscaModel& model)
{
  model.zoom_table = { { 0x0000, 1.0 }, { 0x4000, 2.0 } };  // a placeholder: never used to judge a goal
  model.zoom_table_known = false;
}

ViscaModel ilmeFr7()
{
  // ILME-FR7 command list: 5 + 5 nibbles, two speeds (ww 00: tilt in step with pan); pan F6359h..09CA7h = -170..+170
  // (235.9 steps a degree), tilt FE45Bh (-30)..0B3B0h (+195), desktop, ceiling off. Speed step normal: 01..18h (the
  // table). An interchangeable-lens camera: the X-factor of the zoom positions is the lens's.
  ViscaModel model;
  model.axes = { { tableAxis(235.9, -170.0, 170.0, SONY_NORMAL_SPEEDS),
                   tableAxis(235.9, -30.0, 195.0, SONY_NORMAL_SPEEDS) } };
  model.layout = PositionLayout{ 5, 5, false };
  lensDependentZoom(model);
  model.vendor_id = SONY;
  model.model_id = 0x051E;
  return model;
}

ViscaModel brcAm7()
{
  // BRC-AM7 command list: 5 + 5 nibbles, two speeds; pan D5468h..2AB98h = -175..+175 (1000 steps a degree), tilt
  // F8AD0h (-30)..33450h (+210), ceiling off. Speed step normal: 01..18h (the table). Zoom 0000h..4000h optical: the
  // X-factor of the tele end is not in the command list (not found), so zoom goals need zoom/table.
  ViscaModel model;
  model.axes = { { tableAxis(1000.0, -175.0, 175.0, SONY_NORMAL_SPEEDS),
                   tableAxis(1000.0, -30.0, 210.0, SONY_NORMAL_SPEEDS) } };
  model.layout = PositionLayout{ 5, 5, false };
  lensDependentZoom(model);
  model.vendor_id = SONY;
  return model;
}

const std::vector<std::pair<std::string, std::function<ViscaModel()>>>& presetTable()
{
  static const std::vector<std::pair<std::string, std::function<ViscaModel()>>> table = {
    { "ptzoptics", ptzOptics },  // the PTZOptics G2's, the default since the first release
    { "ptzoptics_g2", ptzOptics },
    { "ptzoptics_g3", ptzOptics },
    { "evi_d70", eviD70 },
    { "evi_d30", eviD30 },
    { "brc_x1000", [] { return brcX1000(0x0519); } },
    { "brc_h800", [] { return brcX1000(0x051A); } },
    { "brc_x400", brcX400 },
    { "srg_360she", srg360she },
    { "ilme_fr7", ilmeFr7 },
    { "brc_am7", brcAm7 },
  };
  return table;
}
}  // namespace

bool ViscaModel::preset(const std::string& name, ViscaModel& model)
{
  for (const auto& [preset_name, make] : presetTable())
  {
    if (preset_name == name)
    {
      model = make();
      model.name = name;
      return true;
    }
  }
  return false;
}

const std::vector<std::string>& ViscaModel::presets()
{
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& row : presetTable())
    {
      list.push_back(row.first);
    }
    return list;
  }();
  return names;
}

std::string ViscaModel::presetNames()
{
  std::string text;
  for (const std::string& name : presets())
  {
    text += (text.empty() ? "" : ", ") + name;
  }
  return text;
}

}  // namespace visca
}  // namespace ptz_action_server
