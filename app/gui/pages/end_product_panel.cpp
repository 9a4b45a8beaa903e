#include "gui/pages/end_product_panel.h"

#include "gui/number_format.h"
#include "i18n/end_product_words.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPixmap>
#include <QTableWidget>
#include <QVBoxLayout>

#include <cmath>

namespace microsim::gui {

EndProductPanel::EndProductPanel(Qt::Orientation orientation, QWidget* parent) : QWidget(parent) {
  setObjectName(QStringLiteral("endProductPanel"));
  auto* caption = new QLabel(
      tr("<b>Opened vessel</b>: cut along its axis and laid flat; 0° faces the microscope. "
         "Dots are passages, blue lines the stitches' thread, numbered marks the errors."),
      this);
  caption->setWordWrap(true);
  picture_ = new QLabel(this);
  picture_->setObjectName(QStringLiteral("openedVesselImage"));
  picture_->setAlignment(Qt::AlignCenter);
  summary_ = new QLabel(this);
  summary_->setObjectName(QStringLiteral("endProductSummary"));
  summary_->setWordWrap(true);
  table_ = new QTableWidget(0, 4, this);
  table_->setObjectName(QStringLiteral("endProductTable"));
  table_->setHorizontalHeaderLabels(columnTitles());
  for (int column = 0; column < 3; ++column)
    table_->horizontalHeader()->setSectionResizeMode(column, QHeaderView::ResizeToContents);
  table_->horizontalHeader()->setSectionResizeMode(3, QHeaderView::Stretch);
  table_->verticalHeader()->hide();
  table_->setEditTriggers(QAbstractItemView::NoEditTriggers);
  table_->setWordWrap(true);

  // wide: the drawing at the left, the caption over the list beside it; narrow: one column
  picture_->setFixedSize(imageSize());
  auto* list = new QVBoxLayout;
  QBoxLayout* layout = nullptr;
  if (orientation == Qt::Horizontal) {
    layout = new QHBoxLayout(this);
    layout->addWidget(picture_, 0, Qt::AlignTop);
    list->addWidget(caption);
  } else {
    layout = new QVBoxLayout(this);
    layout->addWidget(caption);
    layout->addWidget(picture_, 0, Qt::AlignLeft);
  }
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addLayout(list, 1);
  list->addWidget(summary_);
  // the table takes the height; without errors (no table) the words stay at the top
  list->addWidget(table_, 100);
  list->addStretch(1);
  clear();
}

void EndProductPanel::clear() {
  picture_->clear();
  image_ = QImage();
  summary_->clear();
  table_->setRowCount(0);
  table_->hide();
}

void EndProductPanel::setEndProduct(const OpenedVessel& vessel, bool judged) {
  image_ = OpenedVesselImage::draw(vessel, imageSize());
  picture_->setPixmap(QPixmap::fromImage(image_));
  summary_->setText(summary(vessel.errors, judged));
  table_->setRowCount(static_cast<int>(vessel.errors.size()));
  for (std::size_t i = 0; i < vessel.errors.size(); ++i) {
    const QStringList texts = rowTexts(i, vessel.errors[i]);
    for (int column = 0; column < texts.size(); ++column)
      table_->setItem(static_cast<int>(i), column, new QTableWidgetItem(texts[column]));
  }
  table_->setVisible(!vessel.errors.empty());
}

QStringList EndProductPanel::columnTitles() {
  return {tr("#"), tr("Error"), tr("Where"), tr("Measured")};
}

QStringList EndProductPanel::rowTexts(std::size_t index, const assessment::EndProductError& error) {
  return {QString::number(index + 1), i18n::EndProductWords::kind(error.kind), where(error),
          measured(error)};
}

QString EndProductPanel::summary(const std::vector<assessment::EndProductError>& errors,
                                 bool judged) {
  if (!judged)
    return tr(
        "The end product was not judged: this attempt was scored before its errors were kept.");
  if (errors.empty()) return tr("No end-product errors.");
  return tr("End-product errors (Anastomosis Lapse Index): %1").arg(errors.size());
}

QString EndProductPanel::where(const assessment::EndProductError& e) {
  QStringList parts;
  if (e.stitch >= 0) parts << tr("stitch %1").arg(e.stitch + 1);
  if (e.passage >= 0) parts << tr("pierce %1").arg(e.passage + 1);
  if (std::isfinite(e.angleDeg))
    parts << tr("at %1°", "an angle round the vessel").arg(NumberFormat::number(e.angleDeg, 0));
  else
    parts << tr("not located");
  return parts.join(QStringLiteral(", "));
}

QString EndProductPanel::measured(const assessment::EndProductError& e) {
  if (!std::isfinite(e.measured)) return QStringLiteral("–");
  using K = assessment::EndProductErrorKind;
  QString value;
  QString limit;
  switch (e.kind) {
    case K::WideBite:
      value = tr("%1 wall thicknesses").arg(NumberFormat::number(e.measured, 1));
      limit = NumberFormat::value(e.limit, "count");
      break;
    case K::ObliqueStitch:
      value = tr("bites %1 apart").arg(NumberFormat::value(e.measured, "deg"));
      limit = NumberFormat::value(e.limit, "deg");
      break;
    case K::UnequalSpacing:
      value = tr("gap %1 off the mean").arg(NumberFormat::percent(e.measured));
      limit = NumberFormat::percent(e.limit);
      break;
    case K::WallTear:
      value = tr("links torn: %1").arg(std::lround(e.measured));
      break;
    case K::OverTightStitch:
      value = tr("bites squeezed by %1").arg(NumberFormat::percent(e.measured));
      limit = NumberFormat::percent(e.limit);
      break;
    case K::ThreadInLumen:
      value = tr("%1 into the lumen").arg(NumberFormat::value(e.measured, "mm"));
      limit = NumberFormat::value(e.limit, "mm");
      break;
    case K::LargeEdgeOverlap:
      value =
          tr("edges past each other, %1 out of line").arg(NumberFormat::value(e.measured, "mm"));
      limit = NumberFormat::value(e.limit, "mm");
      break;
    default:
      value = NumberFormat::value(e.measured, assessment::endProductErrorUnit(e.kind));
      limit = NumberFormat::value(e.limit, assessment::endProductErrorUnit(e.kind));
      break;
  }
  return std::isfinite(e.limit) ? tr("%1 (limit %2)").arg(value, limit) : value;
}

}  // namespace microsim::gui
