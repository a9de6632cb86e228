#include "ptz_action_server/panel/image_view.h"

#include <QApplication>
#include <QMouseEvent>
#include <QPainter>
#include <QPolygonF>

#include "ptz_action_server/panel/panel_client.h"

namespace ptz_action_server::panel
{
namespace
{
constexpr double CROSSHAIR = 14.0;  ///< widget px: the aim's arms
constexpr double GAP = 4.0;         ///< widget px left open at its centre

WidgetPoint positionOf(const QMouseEvent* event)
{
  return { event->localPos().x(), event->localPos().y() };
}

/// An image pixel's centre in the painter's coordinates (pixel edges on whole numbers).
QPointF paintPoint(const Letterbox& box, const Pixel& pixel)
{
  return { box.left + (pixel.u + 0.5) * box.scale, box.top + (pixel.v + 0.5) * box.scale };
}

/// A line drawn dark under light, to be seen on any picture.
void drawLine(QPainter& painter, const QPointF& from, const QPointF& to, const QColor& colour)
{
  painter.setPen(QPen(QColor(0, 0, 0, 160), 3.0));
  painter.drawLine(from, to);
  painter.setPen(QPen(colour, 1.5));
  painter.drawLine(from, to);
}
}  // namespace

ImageView::ImageView(PanelClient& client, QWidget* parent) : QWidget(parent), client_(client)
{
  setObjectName("image_view");
  setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
  setMinimumSize(160, 90);
  setToolTip("click: centre that point (move_ptz/pixel); drag a box: centre it and zoom until it fills the view");
  // Each new image posts a repaint to the GUI thread; the client calls this on its spinner.
  client_.setFrameListener([this] {
    QMetaObject::invokeMethod(
        this, [this] { takeFrame(); }, Qt::QueuedConnection);
  });
}

ImageView::~ImageView() = default;

QSize ImageView::sizeHint() const
{
  return { 320, 180 };
}

Letterbox ImageView::layout() const
{
  return frame_ ? letterbox(frame_->width, frame_->height, width(), height()) : Letterbox{};
}

void ImageView::setState(const std::optional<PixelAim>& aim, bool aims, const QString& message)
{
  const bool changed = aim_.has_value() != aim.has_value() || (aim && !(*aim == *aim_)) || message != message_;
  aim_ = aim;
  aims_ = aims;
  message_ = message;
  setCursor(aims_ && frame_ ? Qt::CrossCursor : Qt::ArrowCursor);
  // The aim is drawn from the newest poses: repaint at the panel's rate while there is one.
  if (changed || aim_)
  {
    takeFrame();
    update();
  }
}

void ImageView::setVisibilityListener(std::function<void()> listener)
{
  visibility_listener_ = std::move(listener);
}

void ImageView::clear()
{
  frame_.reset();
  image_ = QImage();
  press_.reset();
  pressed_frame_.reset();
  dragging_ = false;
  update();
}

void ImageView::takeFrame()
{
  std::shared_ptr<const ImageFrame> newest = client_.latestFrame();
  if (newest == frame_)
  {
    return;
  }
  frame_ = std::move(newest);
  // A view of the frame's memory, which frame_ keeps alive (and nobody writes to).
  image_ = frame_ ? QImage(frame_->rgb.data, frame_->width, frame_->height, static_cast<int>(frame_->rgb.step),
                           QImage::Format_RGB888) :
                    QImage();
  update();
}

void ImageView::paintEvent(QPaintEvent*)
{
  QPainter painter(this);
  painter.fillRect(rect(), QColor(20, 20, 20));
  aim_drawn_.reset();
  if (!frame_)
  {
    painter.setPen(QColor(200, 200, 200));
    painter.drawText(rect().adjusted(8, 8, -8, -8), Qt::AlignCenter | Qt::TextWordWrap, message_);
    return;
  }
  const Letterbox box = layout();
  painter.setRenderHint(QPainter::SmoothPixmapTransform, box.scale < 1.0);
  painter.drawImage(QRectF(box.left, box.top, box.width(), box.height()), image_);
  painter.setRenderHint(QPainter::Antialiasing);
  drawAim(painter, box);
  if (press_ && dragging_)
  {
    const QRectF band = QRectF(QPointF(press_->x + 0.5, press_->y + 0.5), QPointF(drag_to_.x + 0.5, drag_to_.y + 0.5));
    painter.setPen(QPen(QColor(255, 255, 255), 1.0, Qt::DashLine));
    painter.setBrush(QColor(255, 255, 255, 40));
    painter.drawRect(band.normalized());
  }
}

void ImageView::drawAim(QPainter& painter, const Letterbox& box)
{
  if (!aim_)
  {
    return;
  }
  const double stamp = frame_->stamp();
  aim_drawn_ = aimInImage(*aim_, client_.viewAt(aim_->stamp), frame_->width, frame_->height, client_.viewAt(stamp));
  if (!aim_drawn_)
  {
    return;
  }
  const QColor colour(60, 255, 90);
  if (aim_drawn_->box)
  {
    QPolygonF corners;
    for (const Pixel& corner : aim_drawn_->corners)
    {
      corners << paintPoint(box, corner);
    }
    painter.setBrush(Qt::NoBrush);
    painter.setPen(QPen(QColor(0, 0, 0, 160), 3.0));
    painter.drawPolygon(corners);
    painter.setPen(QPen(colour, 1.5));
    painter.drawPolygon(corners);
  }
  const QPointF centre = paintPoint(box, aim_drawn_->centre);
  for (const QPointF direction : { QPointF(1, 0), QPointF(-1, 0), QPointF(0, 1), QPointF(0, -1) })
  {
    drawLine(painter, centre + direction * GAP, centre + direction * CROSSHAIR, colour);
  }
}

void ImageView::mousePressEvent(QMouseEvent* event)
{
  if (event->button() != Qt::LeftButton || !aims_ || !frame_)
  {
    QWidget::mousePressEvent(event);
    return;
  }
  press_ = positionOf(event);
  pressed_frame_ = frame_;
  drag_to_ = *press_;
  dragging_ = false;
}

void ImageView::mouseMoveEvent(QMouseEvent* event)
{
  if (!press_)
  {
    QWidget::mouseMoveEvent(event);
    return;
  }
  drag_to_ = positionOf(event);
  dragging_ = dragging_ || isDrag(*press_, drag_to_, QApplication::startDragDistance());
  update();
}

void ImageView::mouseReleaseEvent(QMouseEvent* event)
{
  if (!press_ || event->button() != Qt::LeftButton)
  {
    QWidget::mouseReleaseEvent(event);
    return;
  }
  const WidgetPoint from = *press_;
  const WidgetPoint to = positionOf(event);
  const std::shared_ptr<const ImageFrame> frame = std::move(pressed_frame_);
  press_.reset();
  dragging_ = false;
  update();
  // The mapping is the image's shown at the press: the widget may have been resized since, not the image.
  const Letterbox box = letterbox(frame->width, frame->height, width(), height());
  if (isDrag(from, to, QApplication::startDragDistance()))
  {
    if (const std::optional<PixelBox> target = draggedBox(box, from, to))
    {
      client_.aimAtPixel(*frame, *target);
    }
  }
  else if (const std::optional<Pixel> pixel = pixelAt(box, from))
  {
    client_.aimAtPixel(*frame, { pixel->u, pixel->v, 0.0, 0.0 });
  }
}

void ImageView::showEvent(QShowEvent* event)
{
  QWidget::showEvent(event);
  if (visibility_listener_)
  {
    visibility_listener_();
  }
}

void ImageView::hideEvent(QHideEvent* event)
{
  QWidget::hideEvent(event);
  if (visibility_listener_)
  {
    visibility_listener_();
  }
}

}  // namespace ptz_action_server::panel
