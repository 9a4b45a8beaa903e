#include "gui/settings/scene_overrides.h"
#include "gui/settings/settings_dialog.h"
#include "gui/settings/tunables.h"

#include "microsim/sim/scene/scene.h"
#include "support/shipped_files.h"

#include <QComboBox>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace microsim::gui::settings {
namespace {

using microsim::testing::kShippedScene;

TEST(Settings, TheDialogHasAnEditorForEveryTunable) {
  QSettings().clear();
  SettingsDialog dialog;
  for (const Tunable& t : Tunables::all()) {
    QWidget* editor = dialog.editor(t.key);
    ASSERT_NE(editor, nullptr) << t.key.toStdString();
    if (t.type == Tunable::Type::Integer) {
      auto* spin = qobject_cast<QSpinBox*>(editor);
      ASSERT_NE(spin, nullptr);
      EXPECT_EQ(spin->minimum(), t.minimum);
      EXPECT_EQ(spin->maximum(), t.maximum);
      EXPECT_EQ(spin->value(), t.defaultValue.toInt());
    } else {
      auto* combo = qobject_cast<QComboBox*>(editor);
      ASSERT_NE(combo, nullptr);
      EXPECT_EQ(combo->count(), static_cast<int>(t.choices.size()));
      EXPECT_EQ(combo->currentData().toString(), t.defaultValue.toString());
    }
  }
  for (const QString& key : {solverKey(), iterationsKey(), stereoKey(), keyMapKey(), unitsKey()})
    EXPECT_NE(dialog.editor(key), nullptr) << key.toStdString();
}

TEST(Settings, StoresWhatTheDialogShowsAndChecksRanges) {
  QSettings().clear();
  {
    SettingsDialog dialog;
    auto* solver = qobject_cast<QComboBox*>(dialog.editor(solverKey()));
    solver->setCurrentIndex(solver->findData(QStringLiteral("newton")));
    qobject_cast<QSpinBox*>(dialog.editor(iterationsKey()))->setValue(40);
    auto* units = qobject_cast<QComboBox*>(dialog.editor(unitsKey()));
    units->setCurrentIndex(units->findData(QStringLiteral("um")));
    dialog.store();
  }
  EXPECT_EQ(Tunables::value(solverKey()).toString(), QStringLiteral("newton"));
  EXPECT_EQ(Tunables::value(iterationsKey()).toInt(), 40);
  EXPECT_EQ(Tunables::value(unitsKey()).toString(), QStringLiteral("um"));
  // a reopened dialog shows the stored values
  SettingsDialog again;
  EXPECT_EQ(qobject_cast<QComboBox*>(again.editor(solverKey()))->currentData().toString(), QStringLiteral("newton"));

  // out of range or unknown: clamped, or the default
  QSettings().setValue(iterationsKey(), 100000);
  EXPECT_EQ(Tunables::value(iterationsKey()).toInt(), 500);
  QSettings().setValue(stereoKey(), QStringLiteral("hologram"));
  EXPECT_EQ(Tunables::value(stereoKey()).toString(), QStringLiteral("mono"));
  QSettings().clear();
}

TEST(Settings, TheSolverOverrideGivesALoadableSceneWithThatSolver) {
  QTemporaryDir dir;
  EXPECT_EQ(applySolverOverride(kShippedScene, {QStringLiteral("scene"), 0}, dir.path()), kShippedScene);
  QString error;
  const QString patched = applySolverOverride(kShippedScene, {QStringLiteral("newton"), 12}, dir.path(), &error);
  ASSERT_FALSE(patched.isEmpty()) << error.toStdString();
  EXPECT_NE(patched, kShippedScene);
  auto opened = sim::openScene(patched.toStdString());
  ASSERT_TRUE(std::holds_alternative<std::unique_ptr<sim::Scene>>(opened))
      << std::get<sim::SceneError>(opened).field;
  const sim::SceneDef& def = std::get<std::unique_ptr<sim::Scene>>(opened)->def();
  EXPECT_EQ(def.solver.name, "newton");
  EXPECT_EQ(def.solver.iterations, 12);
}

}  // namespace
}  // namespace microsim::gui::settings
