#pragma once
// The finished anastomosis on a page: the opened vessel (opened_vessel_image.h) with its
// errors marked, a line saying how many there are, and their list, numbered as the markers
// are: the kind in words, where it is (stitch, pierce, angle round the vessel) and what was
// measured against its limit. The results page shows it under the pierce angles, the review's
// attempt view in a tab of its own; the review's PDF writes the same words.

#include "gui/pages/opened_vessel_image.h"

#include <QStringList>
#include <QWidget>

class QLabel;
class QTableWidget;

namespace microsim::gui {

class EndProductPanel : public QWidget {
  Q_OBJECT

 public:
  /// Horizontal: the drawing beside the list (a wide page); vertical: above it (a narrow pane).
  explicit EndProductPanel(Qt::Orientation orientation, QWidget* parent = nullptr);

  /// Shows `vessel`; `judged` false: the attempt was never judged for its end product (scored
  /// before the history kept it), which is said rather than shown as clean.
  void setEndProduct(const OpenedVessel& vessel, bool judged);
  void clear();

  QTableWidget* errorTable() const { return table_; }
  QLabel* summaryLabel() const { return summary_; }
  /// The drawing as shown (null image when cleared).
  const QImage& image() const { return image_; }

  /// The list's column titles: number, error, where, measured.
  static QStringList columnTitles();
  /// One error's row under them; `index` is 0-based and shown from 1.
  static QStringList rowTexts(std::size_t index, const assessment::EndProductError& error);
  /// "No end-product errors.", "2 end-product errors ...", or that it was not judged.
  static QString summary(const std::vector<assessment::EndProductError>& errors, bool judged);
  /// "stitch 1, pierce 2, at 182°"; "not located" for an error with no angle and no stitch.
  static QString where(const assessment::EndProductError& error);
  /// "3.4 wall thicknesses (limit 3)"; "–" for a kind that measures nothing.
  static QString measured(const assessment::EndProductError& error);

  /// The drawing's size on a page.
  static QSize imageSize() { return {460, 270}; }

 private:
  QLabel* picture_ = nullptr;
  QLabel* summary_ = nullptr;
  QTableWidget* table_ = nullptr;
  QImage image_;
};

}  // namespace microsim::gui
