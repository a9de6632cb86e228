/**
 * \file
 * \brief PtzPanel, the rviz panel that aims a camera by hand (ptz_action_server/PtzPanel). A thin widget: the texts,
 * velocities and greying come from panel_model.h, the ROS traffic from PanelClient; a 10 Hz timer copies the client's
 * snapshot into the widgets, so nothing on the GUI thread waits on the network.
 */
#pragma once

#include <QString>
#include <memory>
#include <optional>

#include <rviz/panel.h>

#include "ptz_action_server/panel/panel_client.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QListWidget;
class QPushButton;
class QSlider;
class QSpinBox;
class QTimer;
class QVBoxLayout;

namespace ptz_action_server::panel
{
class ImageView;

/// The panel. Child widgets carry object names (jog_right, preset_go, state_pan, ...) for tests and style sheets.
class PtzPanel : public rviz::Panel
{
  Q_OBJECT
public:
  explicit PtzPanel(QWidget* parent = nullptr);
  ~PtzPanel() override;

  void load(const rviz::Config& config) override;
  void save(rviz::Config config) const override;

  /// Watches the camera in `ns` (e.g. "/ptz"), as if picked in the list.
  void setNamespace(const QString& ns);
  /// Copies the client's snapshot into the widgets (the timer's job; tests call it to not wait for the timer).
  void refresh();
  /// Shows the image `topic` ("" for the camera's own, `<namespace>/image_raw`), as if picked in the list.
  void setImageTopic(const QString& topic);

private:
  void build();
  QPushButton* jogButton(const QString& text, const QString& name, Jog jog);
  void pressJog(Jog jog);
  void releaseJog();
  void goToFields();
  void copyStateToFields();
  QString selectedPreset() const;
  // The image view (ptz_panel_image.cpp).
  void buildImage(QVBoxLayout* layout);
  /// The image topic shown: the one picked, else the camera's own.
  QString imageTopic() const;
  /// Subscribes to the image while the view is on and visible, to nothing otherwise.
  void updateImageSubscription();
  void refreshImage(bool aims);
  // The Tours tab (ptz_panel_tours.cpp), beside the Presets tab `presets`.
  void buildTours(QVBoxLayout* layout, QWidget* presets);
  /// Fills the box from last_: the list on news, the tour line, the greying (`moves`: presets may be used).
  void refreshTours(bool fresh, bool moves);
  QString selectedTour() const;

  std::unique_ptr<PanelClient> client_;
  QString ns_;
  std::optional<Jog> pressed_;  ///< the jog control held down
  std::uint64_t presets_serial_ = 0;
  std::uint64_t tours_serial_ = 0;
  PanelSnapshot last_;
  QString image_choice_;  ///< the image topic picked, "" for the camera's own

  QComboBox* camera_ = nullptr;
  QLabel* banner_ = nullptr;
  QLabel* mode_ = nullptr;
  QLabel* pan_ = nullptr;
  QLabel* tilt_ = nullptr;
  QLabel* zoom_ = nullptr;
  QLabel* link_ = nullptr;
  QLabel* goal_ = nullptr;
  QPushButton* left_ = nullptr;
  QPushButton* right_ = nullptr;
  QPushButton* up_ = nullptr;
  QPushButton* down_ = nullptr;
  QPushButton* stop_ = nullptr;
  QPushButton* zoom_in_ = nullptr;
  QPushButton* zoom_out_ = nullptr;
  QSlider* speed_ = nullptr;
  QDoubleSpinBox* pan_field_ = nullptr;
  QDoubleSpinBox* tilt_field_ = nullptr;
  QDoubleSpinBox* zoom_field_ = nullptr;
  QSlider* pan_slider_ = nullptr;
  QSlider* tilt_slider_ = nullptr;
  QPushButton* pose_go_ = nullptr;
  QPushButton* pose_here_ = nullptr;
  QListWidget* presets_ = nullptr;
  QLineEdit* preset_name_ = nullptr;
  QPushButton* preset_go_ = nullptr;
  QPushButton* preset_home_ = nullptr;
  QPushButton* preset_save_ = nullptr;
  QPushButton* preset_delete_ = nullptr;
  QPushButton* preset_refresh_ = nullptr;
  QListWidget* tours_ = nullptr;
  QSpinBox* tour_rounds_ = nullptr;
  QPushButton* tour_start_ = nullptr;
  QPushButton* tour_stop_ = nullptr;
  QPushButton* tour_delete_ = nullptr;
  QPushButton* tour_refresh_ = nullptr;
  QLabel* tour_label_ = nullptr;
  QLabel* tour_progress_ = nullptr;  ///< the tour line, in the state's rows
  QCheckBox* look_ = nullptr;
  QLabel* message_ = nullptr;
  QCheckBox* image_on_ = nullptr;
  QComboBox* image_topic_ = nullptr;
  ImageView* image_view_ = nullptr;
  QTimer* timer_ = nullptr;
};

}  // namespace ptz_action_server::panel
