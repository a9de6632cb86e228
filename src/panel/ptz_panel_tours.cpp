/**
 * \file
 * \brief PtzPanel's Tours tab (beside the Presets tab, for the panel's height): the node's tours, Start (a
 * move_ptz/tour goal), Stop (cancels it), Delete, Refresh; and the Tour row among the state's (any client's tour goal:
 * where it is, or how it ended).
 */
#include <QGridLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

#include "ptz_action_server/panel/ptz_panel.h"

namespace ptz_action_server::panel
{
void PtzPanel::buildTours(QVBoxLayout* layout, QWidget* presets)
{
  const auto make_button = [](const QString& text, const QString& name, const QString& tip) {
    auto* result = new QPushButton(text);
    result->setObjectName(name);
    result->setToolTip(tip);
    return result;
  };
  // No frame and narrow margins: the tabs take no more height than the Presets box they replace, so the image view
  // keeps its size.
  constexpr int MARGIN = 2;
  auto* tabs = new QTabWidget;
  tabs->setObjectName("preset_tabs");
  tabs->setDocumentMode(true);
  presets->setObjectName("presets_page");
  presets->layout()->setContentsMargins(MARGIN, MARGIN, MARGIN, MARGIN);
  tabs->addTab(presets, "Presets");
  auto* box = new QWidget;
  box->setObjectName("tours_page");
  tabs->addTab(box, "Tours");
  auto* grid = new QGridLayout(box);
  grid->setContentsMargins(MARGIN, MARGIN, MARGIN, MARGIN);
  tours_ = new QListWidget;
  tours_->setObjectName("tours");
  tours_->setMaximumHeight(90);
  grid->addWidget(tours_, 0, 0, 4, 1);
  tour_start_ = make_button("Start", "tour_start", "move_ptz/tour: run the selected tour");
  tour_stop_ = make_button("Stop", "tour_stop", "cancel the tour goal, whoever started it (the camera stops)");
  tour_delete_ = make_button("Delete", "tour_delete", "move_ptz/delete_tour of the selected tour");
  tour_refresh_ = make_button("Refresh", "tour_refresh", "move_ptz/list_tours");
  grid->addWidget(tour_start_, 0, 1);
  grid->addWidget(tour_stop_, 1, 1);
  grid->addWidget(tour_delete_, 2, 1);
  grid->addWidget(tour_refresh_, 3, 1);
  auto* rounds_row = new QHBoxLayout;
  tour_rounds_ = new QSpinBox;
  tour_rounds_->setObjectName("tour_rounds");
  tour_rounds_->setRange(0, 1000);
  tour_rounds_->setSpecialValueText("loop");  // 0: until stopped or preempted
  tour_rounds_->setToolTip("rounds to run; loop: until stopped or another goal takes over");
  rounds_row->addWidget(new QLabel("Rounds"));
  rounds_row->addWidget(tour_rounds_, 1);
  grid->addLayout(rounds_row, 4, 0, 1, 2);
  layout->addWidget(tabs);

  const auto start = [this] {
    if (tour_start_->isEnabled() && !selectedTour().isEmpty())  // a double click on the list too, not while greyed
    {
      client_->startTour(selectedTour().toStdString(), static_cast<std::uint32_t>(tour_rounds_->value()));
    }
  };
  connect(tour_start_, &QPushButton::clicked, this, start);
  connect(tours_, &QListWidget::itemDoubleClicked, this, start);
  connect(tour_stop_, &QPushButton::clicked, this, [this] { client_->stopTour(); });
  connect(tour_refresh_, &QPushButton::clicked, this, [this] { client_->refreshTours(); });
  connect(tour_delete_, &QPushButton::clicked, this, [this] {
    if (!selectedTour().isEmpty())
    {
      client_->deleteTour(selectedTour().toStdString());
    }
  });
}

QString PtzPanel::selectedTour() const
{
  const QListWidgetItem* item = tours_->currentItem();
  return item == nullptr ? QString() : item->data(Qt::UserRole).toString();
}

void PtzPanel::refreshTours(bool fresh, bool moves)
{
  const PanelSnapshot& s = last_;
  tour_start_->setEnabled(moves && s.tour_connected);
  tour_stop_->setEnabled(fresh && s.tour_connected);  // as ■: a stop is always offered
  tour_delete_->setEnabled(fresh);
  tour_progress_->setText(QString::fromStdString(s.tour));
  const bool heard = s.tour != NO_TOUR_TEXT;
  tour_label_->setVisible(heard);
  tour_progress_->setVisible(heard);
  if (s.tours_serial == tours_serial_)
  {
    return;
  }
  tours_serial_ = s.tours_serial;
  const QString selected = selectedTour();
  tours_->clear();
  for (const TourListing& tour : s.tours)
  {
    auto* item = new QListWidgetItem(QString::fromStdString(tourListText(tour)));
    item->setData(Qt::UserRole, QString::fromStdString(tour.name));
    item->setToolTip(QString::fromStdString(tourStopsText(tour)));
    tours_->addItem(item);
    if (QString::fromStdString(tour.name) == selected)
    {
      tours_->setCurrentRow(tours_->count() - 1);
    }
  }
}

}  // namespace ptz_action_server::panel
