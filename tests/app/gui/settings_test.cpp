#include "gui/render/stereo_support.h"
#include "gui/settings/scene_overrides.h"
#include "gui/settings/settings_dialog.h"
#include "gui/settings/tunables.h"
#include "i18n/translations.h"

#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/scene_def.h"
#include "support/shipped_files.h"

#include <QComboBox>
#include <QJsonObject>
#include <QSettings>
#include <QSpinBox>
#include <QTranslator>

#include <algorithm>
#include <variant>

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
      const auto offered = std::count_if(t.choices.begin(), t.choices.end(), [](const Choice& c) { return c.isOffered(); });
      EXPECT_EQ(combo->count(), static_cast<int>(offered));
      EXPECT_EQ(combo->currentData().toString(), t.defaultValue.toString());
    }
  }
  for (const QString& key : {solverKey(), iterationsKey(), stereoKey(), keyMapKey(), unitsKey()})
    EXPECT_NE(dialog.editor(key), nullptr) << key.toStdString();
}

// The language list names each language in itself, whatever the interface's language, so a
// trainee who cannot read the present one still finds their own; "System default" is
// translated like every other label.
std::vector<QString> languageLabels() {
  for (const Tunable& t : Tunables::all()) {
    if (t.key != i18n::languageSettingKey()) continue;
    std::vector<QString> labels;
    for (const Choice& c : t.choices) labels.push_back(c.label);
    return labels;
  }
  return {};
}

TEST(Settings, TheLanguagesAreNamedInThemselvesInEveryInterfaceLanguage) {
  const std::vector<QString> english = languageLabels();
  ASSERT_EQ(english.size(), 4U);
  EXPECT_EQ(english[0], QStringLiteral("System default"));
  const std::vector<QString> names{QStringLiteral("English"), QStringLiteral("Deutsch"),
                                   QString::fromUtf8("Español")};
  for (const QString& interface : {QStringLiteral("de"), QStringLiteral("es")}) {
    QTranslator translator;
    ASSERT_TRUE(translator.load(QStringLiteral(":/i18n/microsim_") + interface));
    QCoreApplication::installTranslator(&translator);
    const std::vector<QString> shown = languageLabels();
    QCoreApplication::removeTranslator(&translator);
    ASSERT_EQ(shown.size(), 4U);
    EXPECT_NE(shown[0], english[0])
        << interface.toStdString() << ": \"System default\" untranslated";
    for (std::size_t k = 0; k < names.size(); ++k) {
      EXPECT_EQ(shown[k + 1], names[k]) << interface.toStdString();
      EXPECT_EQ(english[k + 1], names[k]);
    }
  }
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

TEST(Settings, OffersOnlyTheStereoModesThisDisplayCanShow) {
  QSettings().clear();
  // Xvfb has no stereo visual (and Qt 6.4's QOpenGLWidget no left/right buffers)
  ASSERT_FALSE(quadBufferStereoAvailable());
  SettingsDialog dialog;
  auto* stereo = qobject_cast<QComboBox*>(dialog.editor(stereoKey()));
  ASSERT_NE(stereo, nullptr);
  QStringList offered;
  for (int i = 0; i < stereo->count(); ++i) offered << stereo->itemData(i).toString();
  EXPECT_EQ(offered, (QStringList{QStringLiteral("mono"), QStringLiteral("anaglyph"), QStringLiteral("side")}));
  for (int i = 0; i < stereo->count(); ++i)
    EXPECT_FALSE(stereo->itemText(i).contains(QStringLiteral("Quad"))) << stereo->itemText(i).toStdString();

  // a quad-buffer choice stored on another machine reads back as the default here, and the
  // dialog shows that default rather than a mode it does not offer
  QSettings().setValue(stereoKey(), QStringLiteral("quad"));
  EXPECT_EQ(Tunables::value(stereoKey()).toString(), QStringLiteral("mono"));
  SettingsDialog again;
  EXPECT_EQ(qobject_cast<QComboBox*>(again.editor(stereoKey()))->currentData().toString(), QStringLiteral("mono"));
  // the modes that work are stored as chosen
  Tunables::setValue(stereoKey(), QStringLiteral("side"));
  EXPECT_EQ(Tunables::value(stereoKey()).toString(), QStringLiteral("side"));
  QSettings().clear();
}

// the shipped scene's definition, as a test starts from it
sim::SceneDef shippedSceneDef() {
  sim::SceneDefLoad loaded = sim::loadSceneDef(kShippedScene.toStdString());
  EXPECT_TRUE(std::holds_alternative<sim::SceneDef>(loaded));
  return std::holds_alternative<sim::SceneDef>(loaded) ? std::get<sim::SceneDef>(loaded) : sim::SceneDef{};
}

TEST(Settings, TheSolverOverrideChangesTheSceneInMemoryOnly) {
  const sim::SceneDef shipped = shippedSceneDef();

  // "scene" and no budget: the scene as its file says, and no metadata
  sim::SceneDef kept = shipped;
  ASSERT_TRUE(applySolverOverride(kept, {QStringLiteral("scene"), 0}));
  EXPECT_EQ(kept.solver.name, shipped.solver.name);
  EXPECT_EQ(kept.solver.iterations, shipped.solver.iterations);
  EXPECT_TRUE(solverOverrideJson(kept, {QStringLiteral("scene"), 0}).isEmpty());

  // another solver starts from its defaults with the scene's budget, then the given budget
  sim::SceneDef other = shipped;
  ASSERT_TRUE(applySolverOverride(other, {QStringLiteral("qss"), 0}));
  EXPECT_EQ(other.solver.name, "qss");
  EXPECT_EQ(other.solver.iterations, shipped.solver.iterations);
  EXPECT_EQ(other.solver.tolerance, sim::TissueSolverDef{}.tolerance);
  sim::SceneDef budget = shipped;
  const SolverOverride newton12{QStringLiteral("newton"), 12};
  ASSERT_TRUE(applySolverOverride(budget, newton12));
  EXPECT_EQ(budget.solver.name, "newton");
  EXPECT_EQ(budget.solver.iterations, 12);
  EXPECT_EQ(budget.file, shipped.file) << "the recording still names the lesson's own scene file";
  EXPECT_EQ(solverOverrideJson(budget, newton12),
            (QJsonObject{{QStringLiteral("name"), QStringLiteral("newton")}, {QStringLiteral("iterations"), 12}}));
  // the changed definition builds a scene that steps with it
  const sim::Scene scene(budget);
  EXPECT_EQ(scene.def().solver.iterations, 12);

  // an unknown solver is refused and changes nothing
  sim::SceneDef unknown = shipped;
  EXPECT_FALSE(applySolverOverride(unknown, {QStringLiteral("simplex"), 30}));
  EXPECT_EQ(unknown.solver.name, shipped.solver.name);
  EXPECT_EQ(unknown.solver.iterations, shipped.solver.iterations);
}

}  // namespace
}  // namespace microsim::gui::settings
