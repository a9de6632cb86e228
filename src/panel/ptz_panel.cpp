#include "ptz_action_server/panel/ptz_panel.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QGridLayout>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSlider>
#include <QTimer>
#include <QVBoxLayout>
#include <cmath>

#include <pluginlib/class_list_macros.hpp>

#include "ptz_action_server/panel/image_view.h"

namespace ptz_action_server::panel
{
namespace
{
constexpr int REFRESH_MS = 100;
constexpr double DEG = 180.0 / M_PI;

QLabel* valueLabel(const QString& name)
{
  auto* label = new QLabel("-");
  label->setObjectName(name);
  label->setTextInteractionFlags(Qt::TextSelectableByMouse);
  return label;
}

QPushButton* button(const QString& text, const QString& name, const QString& tip)
{
  auto* result = new QPushButton(text);
  result->setObjectName(name);
  result->setToolTip(tip);
  return result;
}

/// Sets a spin box's and a slider's range to an axis' limits (in degrees for angles) once they are known.
void setRange(QDoubleSpinBox* field, QSlider* slider, double min, double max, double scale)
{
  if (!std::isfinite(min) || !std::isfinite(max) || min >= max)
  {
    return;
  }
  field->setRange(min * scale, max * scale);
  if (slider != nullptr)
  {
    slider->setRange(static_cast<int>(std::ceil(min * scale)), static_cast<int>(std::floor(max * scale)));
  }
}
}  // namespace

PtzPanel::PtzPanel(QWidget* parent) : rviz::Panel(parent), client_(std::make_unique<PanelClient>())
{
  build();
  timer_ = new QTimer(this);
  connect(timer_, &QTimer::timeout, this, &PtzPanel::refresh);
  timer_->start(REFRESH_MS);
  setNamespace("/ptz");
}

PtzPanel::~PtzPanel()
{
  // The view outlives client_ (QWidget deletes its children after the members): it must not reach it from here on,
  // neither through its hide event nor through a new image.
  image_view_->setVisibilityListener(nullptr);
  client_->setFrameListener(nullptr);
  if (pressed_)
  {
    client_->stopJog();
  }
}

void PtzPanel::build()
{
  auto* layout = new QVBoxLayout(this);

  auto* camera_row = new QHBoxLayout;
  camera_row->addWidget(new QLabel("Camera"));
  camera_ = new QComboBox;
  camera_->setObjectName("camera");
  camera_->setToolTip("namespace of a ptz_action_server: every namespace with a ptz_state topic");
  camera_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  camera_row->addWidget(camera_);
  layout->addLayout(camera_row);
  connect(camera_, QOverload<int>::of(&QComboBox::activated), this,
          [this](int index) { setNamespace(camera_->itemText(index)); });

  banner_ = new QLabel;
  banner_->setObjectName("banner");
  banner_->setStyleSheet("QLabel { color: #d04040; font-weight: bold; }");
  layout->addWidget(banner_);

  auto* state = new QFormLayout;
  state->addRow("Mode", mode_ = valueLabel("state_mode"));
  state->addRow("Pan", pan_ = valueLabel("state_pan"));
  state->addRow("Tilt", tilt_ = valueLabel("state_tilt"));
  state->addRow("Zoom", zoom_ = valueLabel("state_zoom"));
  state->addRow("Link", link_ = valueLabel("state_link"));
  state->addRow("Goal", goal_ = valueLabel("state_goal"));
  goal_->setWordWrap(true);
  tour_label_ = new QLabel("Tour");  // shown once a tour goal is heard of
  state->addRow(tour_label_, tour_progress_ = valueLabel("tour_progress"));
  tour_progress_->setWordWrap(true);
  layout->addLayout(state);
  buildImage(layout);

  look_ = new QCheckBox("Look at clicked point");
  look_->setObjectName("look_at_clicked_point");
  look_->setToolTip("rviz's Publish Point aims the camera (the node's look_at_clicked_point service)");
  connect(look_, &QCheckBox::clicked, this, [this](bool on) { client_->setLookAt(on); });
  layout->addWidget(look_);

  auto* jog_box = new QGroupBox("Jog (hold)");
  auto* jog = new QGridLayout(jog_box);
  up_ = jogButton("\u25b2", "jog_up", Jog::UP);
  left_ = jogButton("\u25c0", "jog_left", Jog::LEFT);
  right_ = jogButton("\u25b6", "jog_right", Jog::RIGHT);
  down_ = jogButton("\u25bc", "jog_down", Jog::DOWN);
  stop_ = button("\u25a0", "stop", "stop: an all-zero velocity goal, whoever moves the camera");
  connect(stop_, &QPushButton::clicked, this, [this] { client_->stopAll(); });
  zoom_in_ = jogButton("Zoom +", "zoom_in", Jog::ZOOM_IN);
  zoom_out_ = jogButton("Zoom \u2212", "zoom_out", Jog::ZOOM_OUT);
  jog->addWidget(up_, 0, 1);
  jog->addWidget(left_, 1, 0);
  jog->addWidget(stop_, 1, 1);
  jog->addWidget(right_, 1, 2);
  jog->addWidget(down_, 2, 1);
  jog->addWidget(zoom_in_, 0, 3);
  jog->addWidget(zoom_out_, 2, 3);
  speed_ = new QSlider(Qt::Horizontal);
  speed_->setObjectName("speed");
  speed_->setRange(5, 100);
  speed_->setValue(30);
  speed_->setToolTip("jog speed, % of each axis' max speed");
  jog->addWidget(new QLabel("Speed"), 3, 0);
  jog->addWidget(speed_, 3, 1, 1, 3);
  layout->addWidget(jog_box);

  auto* pose_box = new QGroupBox("Pose");
  auto* pose = new QGridLayout(pose_box);
  pan_field_ = new QDoubleSpinBox;
  pan_field_->setObjectName("pose_pan");
  pan_field_->setRange(-180.0, 180.0);
  pan_field_->setSuffix("\u00b0");
  tilt_field_ = new QDoubleSpinBox;
  tilt_field_->setObjectName("pose_tilt");
  tilt_field_->setRange(-90.0, 90.0);
  tilt_field_->setSuffix("\u00b0");
  zoom_field_ = new QDoubleSpinBox;
  zoom_field_->setObjectName("pose_zoom");
  zoom_field_->setRange(0.0, 100.0);
  zoom_field_->setValue(1.0);
  zoom_field_->setSuffix(" x");
  pan_slider_ = new QSlider(Qt::Horizontal);
  pan_slider_->setObjectName("pose_pan_slider");
  pan_slider_->setRange(-180, 180);
  tilt_slider_ = new QSlider(Qt::Horizontal);
  tilt_slider_->setObjectName("pose_tilt_slider");
  tilt_slider_->setRange(-90, 90);
  // Dragging a slider moves its field; letting go sends the goal.
  connect(pan_slider_, &QSlider::sliderMoved, pan_field_, [this](int value) { pan_field_->setValue(value); });
  connect(tilt_slider_, &QSlider::sliderMoved, tilt_field_, [this](int value) { tilt_field_->setValue(value); });
  // Typed values move the sliders (setValue emits no sliderMoved, so no loop).
  connect(pan_field_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), pan_slider_,
          [this](double value) { pan_slider_->setValue(static_cast<int>(std::lround(value))); });
  connect(tilt_field_, QOverload<double>::of(&QDoubleSpinBox::valueChanged), tilt_slider_,
          [this](double value) { tilt_slider_->setValue(static_cast<int>(std::lround(value))); });
  connect(pan_slider_, &QSlider::sliderReleased, this, &PtzPanel::goToFields);
  connect(tilt_slider_, &QSlider::sliderReleased, this, &PtzPanel::goToFields);
  pose->addWidget(new QLabel("Pan"), 0, 0);
  pose->addWidget(pan_field_, 0, 1);
  pose->addWidget(pan_slider_, 0, 2);
  pose->addWidget(new QLabel("Tilt"), 1, 0);
  pose->addWidget(tilt_field_, 1, 1);
  pose->addWidget(tilt_slider_, 1, 2);
  pose->addWidget(new QLabel("Zoom"), 2, 0);
  pose->addWidget(zoom_field_, 2, 1);
  auto* pose_buttons = new QHBoxLayout;
  pose_here_ = button("Current", "pose_here", "copy the camera's pose into the fields");
  pose_go_ = button("Go", "pose_go", "move_ptz/position_abs to the fields' pose");
  connect(pose_here_, &QPushButton::clicked, this, &PtzPanel::copyStateToFields);
  connect(pose_go_, &QPushButton::clicked, this, &PtzPanel::goToFields);
  pose_buttons->addWidget(pose_here_);
  pose_buttons->addWidget(pose_go_);
  pose->addLayout(pose_buttons, 2, 2);
  layout->addWidget(pose_box);

  auto* preset_box = new QWidget;  // a tab beside the Tours (buildTours)
  auto* presets = new QGridLayout(preset_box);
  presets_ = new QListWidget;
  presets_->setObjectName("presets");
  presets_->setMaximumHeight(90);
  connect(presets_, &QListWidget::itemDoubleClicked, this,
          [this] { client_->goPreset(selectedPreset().toStdString()); });
  connect(presets_, &QListWidget::currentItemChanged, this, [this] {
    const QString name = selectedPreset();
    if (!name.isEmpty() && name != "home")
    {
      preset_name_->setText(name);
    }
  });
  presets->addWidget(presets_, 0, 0, 4, 1);
  preset_go_ = button("Go", "preset_go", "move_ptz/preset to the selected preset");
  preset_home_ = button("Home", "preset_home", "move_ptz/preset home");
  preset_refresh_ = button("Refresh", "preset_refresh", "move_ptz/list_presets");
  preset_delete_ = button("Delete", "preset_delete", "move_ptz/delete_preset of the selected preset");
  presets->addWidget(preset_go_, 0, 1);
  presets->addWidget(preset_home_, 1, 1);
  presets->addWidget(preset_delete_, 2, 1);
  presets->addWidget(preset_refresh_, 3, 1);
  preset_name_ = new QLineEdit;
  preset_name_->setObjectName("preset_name");
  preset_name_->setPlaceholderText("name");
  preset_save_ = button("Save", "preset_save", "move_ptz/save_preset: the current pose under this name");
  presets->addWidget(preset_name_, 4, 0);
  presets->addWidget(preset_save_, 4, 1);
  connect(preset_go_, &QPushButton::clicked, this, [this] {
    if (!selectedPreset().isEmpty())
    {
      client_->goPreset(selectedPreset().toStdString());
    }
  });
  connect(preset_home_, &QPushButton::clicked, this, [this] { client_->goPreset("home"); });
  connect(preset_refresh_, &QPushButton::clicked, this, [this] { client_->refreshPresets(); });
  connect(preset_delete_, &QPushButton::clicked, this, [this] {
    if (!selectedPreset().isEmpty())
    {
      client_->deletePreset(selectedPreset().toStdString());
    }
  });
  connect(preset_save_, &QPushButton::clicked, this, [this] {
    if (!preset_name_->text().trimmed().isEmpty())
    {
      client_->savePreset(preset_name_->text().trimmed().toStdString());
    }
  });
  buildTours(layout, preset_box);

  message_ = new QLabel;
  message_->setObjectName("message");
  message_->setWordWrap(true);
  layout->addWidget(message_);
  layout->addStretch(1);
}

QPushButton* PtzPanel::jogButton(const QString& text, const QString& name, Jog jog)
{
  QPushButton* result = button(text, name, "hold to move (a velocity goal), let go to stop");
  connect(result, &QPushButton::pressed, this, [this, jog] { pressJog(jog); });
  connect(result, &QPushButton::released, this, &PtzPanel::releaseJog);
  return result;
}

void PtzPanel::pressJog(Jog jog)
{
  pressed_ = jog;
  client_->jog(jogVelocity(jog, speed_->value() / 100.0, last_.abilities));
}

void PtzPanel::releaseJog()
{
  if (pressed_)
  {
    pressed_.reset();
    client_->stopJog();
  }
}

void PtzPanel::goToFields()
{
  client_->goAbsolute(pan_field_->value() / DEG, tilt_field_->value() / DEG, zoom_field_->value());
}

void PtzPanel::copyStateToFields()
{
  if (!last_.has_state)
  {
    return;
  }
  if (std::isfinite(last_.pan))
  {
    pan_field_->setValue(last_.pan * DEG);
    pan_slider_->setValue(static_cast<int>(std::lround(last_.pan * DEG)));
  }
  if (std::isfinite(last_.tilt))
  {
    tilt_field_->setValue(last_.tilt * DEG);
    tilt_slider_->setValue(static_cast<int>(std::lround(last_.tilt * DEG)));
  }
  if (std::isfinite(last_.zoom))
  {
    zoom_field_->setValue(last_.zoom);
  }
}

QString PtzPanel::selectedPreset() const
{
  const QListWidgetItem* item = presets_->currentItem();
  return item == nullptr ? QString() : item->data(Qt::UserRole).toString();
}

void PtzPanel::setNamespace(const QString& ns)
{
  releaseJog();
  ns_ = ns;
  client_->setNamespace(ns.toStdString());
  presets_serial_ = 0;
  presets_->clear();
  tours_serial_ = 0;
  tours_->clear();
  if (camera_->findText(ns) < 0)
  {
    camera_->addItem(ns);
  }
  camera_->setCurrentText(ns);
  updateImageSubscription();  // the camera's own image follows the camera
  refresh();
  Q_EMIT configChanged();
}

void PtzPanel::refresh()
{
  const bool first_state = !last_.has_state;
  last_ = client_->snapshot();
  const PanelSnapshot& s = last_;

  // The camera list: the master's cameras, and the one watched even while it is gone.
  QStringList names;
  for (const std::string& ns : s.namespaces)
  {
    names << QString::fromStdString(ns);
  }
  if (!ns_.isEmpty() && !names.contains(ns_))
  {
    names << ns_;
  }
  QStringList shown;
  for (int i = 0; i < camera_->count(); ++i)
  {
    shown << camera_->itemText(i);
  }
  if (names != shown && !camera_->view()->isVisible())
  {
    camera_->clear();
    camera_->addItems(names);
    camera_->setCurrentText(ns_);
  }

  banner_->setText(QString::fromStdString(s.banner));
  banner_->setVisible(!s.banner.empty());
  mode_->setText(s.has_state ? QString::fromStdString(modeText(s.mode)) : "-");
  pan_->setText(s.has_state ? QString::fromStdString(angleText(s.pan)) : "-");
  tilt_->setText(s.has_state ? QString::fromStdString(angleText(s.tilt)) : "-");
  zoom_->setText(s.has_state ? QString::fromStdString(zoomText(s.zoom)) : "-");
  link_->setText(QString::fromStdString(linkText(s.link)));
  goal_->setText(QString::fromStdString(s.goal));
  message_->setText(QString::fromStdString(s.message));

  EnableInputs inputs;
  inputs.fresh = s.fresh && s.actions_connected;
  inputs.link = s.link;
  inputs.abilities = s.abilities;
  inputs.look_available = s.look_available;
  const Enables e = enables(inputs);
  left_->setEnabled(e.jog_pan);
  right_->setEnabled(e.jog_pan);
  up_->setEnabled(e.jog_tilt);
  down_->setEnabled(e.jog_tilt);
  zoom_in_->setEnabled(e.jog_zoom);
  zoom_out_->setEnabled(e.jog_zoom);
  stop_->setEnabled(inputs.fresh);
  speed_->setEnabled(e.jog_pan || e.jog_tilt || e.jog_zoom);
  for (QWidget* widget :
       { static_cast<QWidget*>(pan_field_), static_cast<QWidget*>(tilt_field_), static_cast<QWidget*>(zoom_field_),
         static_cast<QWidget*>(pan_slider_), static_cast<QWidget*>(tilt_slider_), static_cast<QWidget*>(pose_go_),
         static_cast<QWidget*>(pose_here_) })
  {
    widget->setEnabled(e.absolute);
  }
  for (QWidget* widget : { preset_go_, preset_home_, preset_save_, preset_delete_ })
  {
    widget->setEnabled(e.presets);
  }
  look_->setEnabled(e.look_switch);
  refreshTours(inputs.fresh, e.presets);
  refreshImage(inputs.fresh && s.link != Link::DOWN);
  if (look_->isChecked() != s.look_enabled)
  {
    look_->setChecked(s.look_enabled);  // setChecked emits no clicked: no service call
  }
  // A held control that got greyed (the node went away) sends no release: stop here.
  if (pressed_ && !inputs.fresh)
  {
    releaseJog();
  }

  if (s.abilities.known)
  {
    setRange(pan_field_, pan_slider_, s.abilities.pan.min, s.abilities.pan.max, DEG);
    setRange(tilt_field_, tilt_slider_, s.abilities.tilt.min, s.abilities.tilt.max, DEG);
    setRange(zoom_field_, nullptr, s.abilities.zoom.min, s.abilities.zoom.max, 1.0);
  }
  if (first_state && s.has_state)
  {
    copyStateToFields();
  }
  if (s.presets_serial != presets_serial_)
  {
    presets_serial_ = s.presets_serial;
    const QString selected = selectedPreset();
    presets_->clear();
    for (const Preset& preset : s.presets)
    {
      auto* item = new QListWidgetItem(QString("%1  (%2\u00b0, %3\u00b0, %4 x)")
                                           .arg(QString::fromStdString(preset.name))
                                           .arg(preset.pan * DEG, 0, 'f', 1)
                                           .arg(preset.tilt * DEG, 0, 'f', 1)
                                           .arg(preset.zoom, 0, 'f', 1));
      item->setData(Qt::UserRole, QString::fromStdString(preset.name));
      presets_->addItem(item);
      if (QString::fromStdString(preset.name) == selected)
      {
        presets_->setCurrentRow(presets_->count() - 1);
      }
    }
  }
}

}  // namespace ptz_action_server::panel

PLUGINLIB_EXPORT_CLASS(ptz_action_server::panel::PtzPanel, rviz::Panel)
