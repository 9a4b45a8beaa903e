#include "gui/screenshots.h"

#include <QDir>
#include <QImage>
#include <QSettings>
#include <QSurfaceFormat>
#include <QTemporaryDir>

#include "app/gui/core_profile.h"

#include <gtest/gtest.h>

#include <set>

namespace microsim::gui {
namespace {

TEST(Screenshots, WritesEveryMainScreen) {
  QSettings().clear();
  requestCoreProfile();

  QTemporaryDir dir;
  QString error;
  const QStringList files = writeScreenshots(dir.path(), &error, 1024, 640);
  ASSERT_EQ(files.size(), 11) << error.toStdString();
  QStringList names;
  for (const QString& f : files) {
    names << QFileInfo(f).fileName();
    const QImage image(f);
    ASSERT_FALSE(image.isNull()) << f.toStdString();
    // a real screen has many colours, not a blank
    std::set<QRgb> colours;
    for (int y = 0; y < image.height(); y += 4)
      for (int x = 0; x < image.width(); x += 4) colours.insert(image.pixel(x, y));
    EXPECT_GT(colours.size(), 8u) << f.toStdString();
  }
  EXPECT_EQ(names,
            (QStringList{QStringLiteral("sign-in.png"), QStringLiteral("lessons.png"),
                         QStringLiteral("attempt-learn.png"), QStringLiteral("microscope-top.png"),
                         QStringLiteral("microscope-oblique.png"), QStringLiteral("results.png"),
                         QStringLiteral("settings.png"), QStringLiteral("review-grid.png"),
                         QStringLiteral("review-history.png"), QStringLiteral("review-attempt.png"),
                         QStringLiteral("review-end-product.png")}));
  EXPECT_EQ(QImage(files[0]).width(), 1024);
}

}  // namespace
}  // namespace microsim::gui
