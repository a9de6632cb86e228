/**
 * \file
 * \brief ImageView, the panel's picture: the newest image PanelClient converted, scaled to the widget with its aspect
 * ratio kept; a click centres the pixel clicked, a dragged box is centred and zoomed to (move_ptz/pixel goals on the
 * image shown when the button went down); the pixel goal under way is drawn over the picture. The mapping between
 * widget and image is image_view_model.h's.
 */
#pragma once

#include <QImage>
#include <QString>
#include <QWidget>
#include <functional>
#include <memory>
#include <optional>

#include "ptz_action_server/panel/image_frame.h"
#include "ptz_action_server/panel/image_view_model.h"

namespace ptz_action_server::panel
{
class PanelClient;

class ImageView : public QWidget
{
public:
  /// Shows `client`'s images, told of each new one by the client's frame listener, which it sets; the client must
  /// outlive the widget or have its listener cleared first (PtzPanel does).
  explicit ImageView(PanelClient& client, QWidget* parent = nullptr);
  ~ImageView() override;

  /// The image shown; null before the first. Tests find pixels in it and map them with layout().
  std::shared_ptr<const ImageFrame> frame() const
  {
    return frame_;
  }
  /// Where the image shown lies in the widget.
  Letterbox layout() const;
  /// The pixel goal as the last paint drew it, in the image's pixels; nullopt when none was drawn.
  std::optional<AimInImage> aimDrawn() const
  {
    return aim_drawn_;
  }
  /// What the panel's snapshot says: the pixel goal to draw, whether a click may aim (the panel's greying), and the
  /// text shown while there is no image.
  void setState(const std::optional<PixelAim>& aim, bool aims, const QString& message);
  /// Called whenever the widget is shown or hidden (the panel subscribes to the image only while it is shown).
  void setVisibilityListener(std::function<void()> listener);
  /// Drops the image shown (another topic was picked).
  void clear();

  QSize sizeHint() const override;

protected:
  void paintEvent(QPaintEvent* event) override;
  void mousePressEvent(QMouseEvent* event) override;
  void mouseMoveEvent(QMouseEvent* event) override;
  void mouseReleaseEvent(QMouseEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void hideEvent(QHideEvent* event) override;

private:
  /// The client's newest image, if it is new.
  void takeFrame();
  void drawAim(QPainter& painter, const Letterbox& box);

  PanelClient& client_;
  std::shared_ptr<const ImageFrame> frame_;
  QImage image_;  ///< a view of frame_'s pixels, no copy
  std::optional<PixelAim> aim_;
  std::optional<AimInImage> aim_drawn_;
  bool aims_ = false;
  QString message_;
  std::function<void()> visibility_listener_;
  /// The button went down here (widget position), on this image: the goal is on the image shown then.
  std::optional<WidgetPoint> press_;
  std::shared_ptr<const ImageFrame> pressed_frame_;
  WidgetPoint drag_to_;
  bool dragging_ = false;
};

}  // namespace ptz_action_server::panel
