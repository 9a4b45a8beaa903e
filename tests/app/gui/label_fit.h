#pragma once
// Whether every text on a screen fits the widget that shows it, for the GUI tests: a label,
// button, check box, group-box title, combo box, table header section or table cell whose
// text is wider (or, wrapped, taller) than the room it has would be cut off or elided; two
// sibling labels or buttons whose rectangles intersect would be drawn over each other; a
// label reaching past its parent's edge is cut off there. Each problem is one line naming
// the widget, its text and the sizes.
//
// Sizes come from the widgets' own size hints, which follow the style and the font (a
// non-wrapping label needs its sizeHint, a wrapping one heightForWidth at its width, a
// button its sizeHint), so the check measures what Qt would draw, not an estimate.

#include <QAbstractButton>
#include <QAbstractItemModel>
#include <QAbstractScrollArea>
#include <QComboBox>
#include <QFontMetrics>
#include <QGroupBox>
#include <QHeaderView>
#include <QLabel>
#include <QStyle>
#include <QStyleOptionComboBox>
#include <QTableView>
#include <QWidget>

#include <algorithm>
#include <limits>

namespace microsim::testing {

// a widget as a problem line names it: class, object name, text
inline QString describeWidgetForFit(const QWidget* widget, const QString& text) {
  QString name = QString::fromLatin1(widget->metaObject()->className());
  if (!widget->objectName().isEmpty()) name += QLatin1Char('#') + widget->objectName();
  return QStringLiteral("%1 \"%2\"").arg(name, text.simplified().left(80));
}

inline QString sizeText(QSize size) { return QStringLiteral("%1×%2").arg(size.width()).arg(size.height()); }

// the text shown for `text` on a button or title: mnemonics' '&' not drawn
inline QString withoutMnemonics(QString text) {
  text.replace(QStringLiteral("&&"), QStringLiteral("\x01"));
  text.remove(QLatin1Char('&'));
  text.replace(QLatin1Char('\x01'), QLatin1Char('&'));
  return text;
}

inline void checkLabelFits(const QLabel* label, QStringList& problems) {
  if (label->text().isEmpty() || !label->pixmap().isNull()) return;
  const QSize has = label->size();
  if (label->wordWrap()) {
    // the longest word must fit the width, and the wrapped text the height
    const int longestWord = label->minimumSizeHint().width();
    const int height = label->heightForWidth(has.width());
    if (longestWord > has.width() || height > has.height()) {
      problems << QStringLiteral("%1 wraps to %2 px high (longest word %3 px) in %4")
                      .arg(describeWidgetForFit(label, label->text()))
                      .arg(height)
                      .arg(longestWord)
                      .arg(sizeText(has));
    }
    return;
  }
  const QSize needs = label->sizeHint();
  if (needs.width() > has.width() || needs.height() > has.height()) {
    problems << QStringLiteral("%1 needs %2, has %3")
                    .arg(describeWidgetForFit(label, label->text()), sizeText(needs), sizeText(has));
  }
}

inline void checkButtonFits(const QAbstractButton* button, QStringList& problems) {
  if (button->text().isEmpty()) return;
  const QSize needs = button->sizeHint();
  const QSize has = button->size();
  if (needs.width() > has.width() || needs.height() > has.height()) {
    problems << QStringLiteral("%1 needs %2, has %3")
                    .arg(describeWidgetForFit(button, withoutMnemonics(button->text())), sizeText(needs), sizeText(has));
  }
}

inline void checkGroupBoxFits(const QGroupBox* box, QStringList& problems) {
  if (box->title().isEmpty()) return;
  const QString title = withoutMnemonics(box->title());
  // the title's own width, plus the check box when it has one, against the room for it
  int needs = QFontMetrics(box->font()).horizontalAdvance(title);
  if (box->isCheckable()) {
    needs += box->style()->pixelMetric(QStyle::PM_IndicatorWidth, nullptr, box) +
             box->style()->pixelMetric(QStyle::PM_CheckBoxLabelSpacing, nullptr, box);
  }
  if (needs > box->width())
    problems << QStringLiteral("%1 title needs %2 px, has %3").arg(describeWidgetForFit(box, title)).arg(needs).arg(box->width());
}

inline void checkComboBoxFits(const QComboBox* combo, QStringList& problems) {
  const QString text = combo->currentText();
  if (text.isEmpty()) return;
  QStyleOptionComboBox option;
  option.initFrom(combo);
  option.editable = combo->isEditable();
  option.frame = combo->hasFrame();
  option.currentText = text;
  const QRect field = combo->style()->subControlRect(QStyle::CC_ComboBox, &option, QStyle::SC_ComboBoxEditField, combo);
  const int needs = QFontMetrics(combo->font()).horizontalAdvance(text);
  if (needs > field.width())
    problems << QStringLiteral("%1 needs %2 px, its field has %3").arg(describeWidgetForFit(combo, text)).arg(needs).arg(field.width());
}

inline void checkHeaderFits(const QHeaderView* header, QStringList& problems) {
  if (header->orientation() != Qt::Horizontal || !header->model()) return;
  for (int section = 0; section < header->count(); ++section) {
    if (header->isSectionHidden(section)) continue;
    const QString text = header->model()->headerData(section, Qt::Horizontal, Qt::DisplayRole).toString();
    if (text.isEmpty()) continue;
    const int needs = header->sectionSizeHint(section);
    const int has = header->sectionSize(section);
    if (needs > has)
      problems << QStringLiteral("%1 header needs %2 px, has %3").arg(describeWidgetForFit(header, text)).arg(needs).arg(has);
  }
}

// each cell's text against its column's width and its row's height, as the item delegate
// lays it out: a margin each side, wrapped at word boundaries when the view wraps
inline void checkTableCellsFit(const QTableView* table, QStringList& problems) {
  const QAbstractItemModel* model = table->model();
  if (!model) return;
  const int margin = table->style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, table) + 1;
  for (int row = 0; row < model->rowCount(); ++row) {
    if (table->isRowHidden(row)) continue;
    for (int column = 0; column < model->columnCount(); ++column) {
      if (table->isColumnHidden(column)) continue;
      const QModelIndex index = model->index(row, column);
      const QString text = index.data(Qt::DisplayRole).toString();
      if (text.isEmpty()) continue;
      const QVariant font = index.data(Qt::FontRole);
      const QFontMetrics metrics(font.isValid() ? font.value<QFont>() : table->font());
      const int width = table->columnWidth(column) - 2 * margin;
      const int flags = table->wordWrap() ? int(Qt::TextWordWrap) : 0;
      const QRect needs = metrics.boundingRect(QRect(0, 0, std::max(width, 1), std::numeric_limits<int>::max() / 2),
                                               flags, text);
      if (needs.width() > width || needs.height() > table->rowHeight(row)) {
        problems << QStringLiteral("%1 cell (%2, %3) needs %4, has %5×%6")
                        .arg(describeWidgetForFit(table, text))
                        .arg(row)
                        .arg(column)
                        .arg(sizeText(needs.size()))
                        .arg(width)
                        .arg(table->rowHeight(row));
      }
    }
  }
}

// a widget that shows a text of its own, for the overlap and edge checks
inline bool showsOwnText(const QWidget* widget) {
  if (const auto* label = qobject_cast<const QLabel*>(widget)) return !label->text().isEmpty();
  if (const auto* button = qobject_cast<const QAbstractButton*>(widget)) return !button->text().isEmpty();
  if (const auto* box = qobject_cast<const QGroupBox*>(widget)) return !box->title().isEmpty();
  return false;
}

// a scroll area's contents may be larger than the viewport that shows them
inline bool isScrollViewport(const QWidget* widget) {
  const auto* area = widget->parentWidget() ? qobject_cast<const QAbstractScrollArea*>(widget->parentWidget()) : nullptr;
  return area && area->viewport() == widget;
}

inline void checkSiblingsApart(const QWidget* parent, QStringList& problems) {
  QList<const QWidget*> texts;
  for (const QObject* child : parent->children()) {
    const auto* widget = qobject_cast<const QWidget*>(child);
    if (!widget || widget->isWindow() || !widget->isVisible() || !showsOwnText(widget)) continue;
    texts << widget;
    if (!isScrollViewport(parent) && !parent->rect().contains(widget->geometry())) {
      problems << QStringLiteral("%1 at %2,%3 %4 reaches past its parent %5 (%6)")
                      .arg(describeWidgetForFit(widget, widget->property("text").toString()))
                      .arg(widget->x())
                      .arg(widget->y())
                      .arg(sizeText(widget->size()), describeWidgetForFit(parent, QString()), sizeText(parent->size()));
    }
  }
  for (qsizetype i = 0; i < texts.size(); ++i) {
    for (qsizetype j = i + 1; j < texts.size(); ++j) {
      if (texts[i]->geometry().intersects(texts[j]->geometry())) {
        problems << QStringLiteral("%1 overlaps %2")
                        .arg(describeWidgetForFit(texts[i], texts[i]->property("text").toString()),
                             describeWidgetForFit(texts[j], texts[j]->property("text").toString()));
      }
    }
  }
}

/// Every problem of fit on the visible widgets of `screen` (the screen itself included).
inline QStringList labelFitProblems(const QWidget& screen) {
  QStringList problems;
  QList<const QWidget*> widgets{&screen};
  for (const QWidget* w : screen.findChildren<QWidget*>()) widgets << w;
  for (const QWidget* widget : widgets) {
    if (!widget->isVisible()) continue;
    if (const auto* label = qobject_cast<const QLabel*>(widget)) checkLabelFits(label, problems);
    if (const auto* button = qobject_cast<const QAbstractButton*>(widget)) checkButtonFits(button, problems);
    if (const auto* box = qobject_cast<const QGroupBox*>(widget)) checkGroupBoxFits(box, problems);
    if (const auto* combo = qobject_cast<const QComboBox*>(widget)) checkComboBoxFits(combo, problems);
    if (const auto* header = qobject_cast<const QHeaderView*>(widget)) checkHeaderFits(header, problems);
    if (const auto* table = qobject_cast<const QTableView*>(widget)) checkTableCellsFit(table, problems);
    checkSiblingsApart(widget, problems);
  }
  return problems;
}

}  // namespace microsim::testing
