/**
 * \file
 * \brief PtzPanel's image view (the topic picked, the view, when it subscribes) and the panel's rviz config.
 */
#include <QAbstractItemView>
#include <QCheckBox>
#include <QComboBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLineEdit>
#include <QVBoxLayout>

#include "ptz_action_server/panel/image_view.h"
#include "ptz_action_server/panel/ptz_panel.h"

namespace ptz_action_server::panel
{
void PtzPanel::buildImage(QVBoxLayout* layout)
{
  auto* box = new QGroupBox("Image");
  auto* column = new QVBoxLayout(box);
  auto* row = new QHBoxLayout;
  image_on_ = new QCheckBox;
  image_on_->setObjectName("image_on");
  image_on_->setChecked(true);
  image_on_->setToolTip("show the image (subscribed only while shown)");
  image_topic_ = new QComboBox;
  image_topic_->setObjectName("image_topic");
  image_topic_->setEditable(true);
  image_topic_->setInsertPolicy(QComboBox::NoInsert);
  image_topic_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  image_topic_->setToolTip("a sensor_msgs/Image topic (through image_transport); empty: the camera's image_raw");
  row->addWidget(image_on_);
  row->addWidget(image_topic_);
  column->addLayout(row);
  image_view_ = new ImageView(*client_);
  column->addWidget(image_view_, 1);
  layout->addWidget(box, 3);

  connect(image_on_, &QCheckBox::toggled, this, [this](bool on) {
    image_view_->setVisible(on);  // its hide and show events update the subscription
    Q_EMIT configChanged();
  });
  connect(image_topic_, QOverload<int>::of(&QComboBox::activated), this,
          [this](int index) { setImageTopic(image_topic_->itemText(index)); });
  connect(image_topic_->lineEdit(), &QLineEdit::editingFinished, this,
          [this] { setImageTopic(image_topic_->currentText().trimmed()); });
  image_view_->setVisibilityListener([this] { updateImageSubscription(); });
}

QString PtzPanel::imageTopic() const
{
  return image_choice_.isEmpty() ? QString::fromStdString(defaultImageTopic(ns_.toStdString())) : image_choice_;
}

void PtzPanel::setImageTopic(const QString& topic)
{
  const QString own = QString::fromStdString(defaultImageTopic(ns_.toStdString()));
  image_choice_ = topic == own ? QString() : topic;
  image_topic_->setCurrentText(imageTopic());
  updateImageSubscription();
  Q_EMIT configChanged();
}

void PtzPanel::updateImageSubscription()
{
  if (image_view_ == nullptr)
  {
    return;
  }
  const QString topic = image_view_->isVisible() ? imageTopic() : QString();
  if (QString::fromStdString(client_->snapshot().image_topic) != topic)
  {
    image_view_->clear();
    client_->setImageTopic(topic.toStdString());
  }
}

void PtzPanel::refreshImage(bool aims)
{
  // The master's image topics, and the one shown even while it is not there; left alone while the list is open or
  // a name is being typed.
  QStringList names;
  for (const std::string& topic : last_.image_topics)
  {
    names << QString::fromStdString(topic);
  }
  const QString shown = imageTopic();
  if (!shown.isEmpty() && !names.contains(shown))
  {
    names.prepend(shown);
  }
  QStringList listed;
  for (int i = 0; i < image_topic_->count(); ++i)
  {
    listed << image_topic_->itemText(i);
  }
  if (!image_topic_->view()->isVisible() && !image_topic_->lineEdit()->hasFocus())
  {
    if (names != listed)
    {
      image_topic_->clear();
      image_topic_->addItems(names);
    }
    if (image_topic_->currentText() != shown)
    {
      image_topic_->setCurrentText(shown);
    }
  }
  QString message = QString::fromStdString(last_.image_message);
  if (message.isEmpty() && !image_view_->frame())
  {
    message = "waiting for " + shown;
  }
  image_view_->setState(last_.pixel_aim, aims && last_.pixel_connected, message);
}

void PtzPanel::load(const rviz::Config& config)
{
  rviz::Panel::load(config);
  QString ns;
  if (config.mapGetString("Namespace", &ns) && !ns.isEmpty())
  {
    setNamespace(ns);
  }
  QString topic;
  if (config.mapGetString("Image Topic", &topic))
  {
    setImageTopic(topic);
  }
  bool on = true;
  if (config.mapGetBool("Show Image", &on))
  {
    image_on_->setChecked(on);
  }
}

void PtzPanel::save(rviz::Config config) const
{
  rviz::Panel::save(config);
  config.mapSetValue("Namespace", ns_);
  config.mapSetValue("Image Topic", image_choice_);
  config.mapSetValue("Show Image", image_on_->isChecked());
}

}  // namespace ptz_action_server::panel
