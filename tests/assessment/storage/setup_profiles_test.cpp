// Setup profiles: save, list, load, replace and remove on a real temporary SQLite file;
// export and import as JSON; malformed JSON refused with the field at fault.
#include "microsim/assessment/storage/setup_profiles.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <functional>

namespace microsim::assessment {
namespace {

SetupProfile sampleProfile(const QString& name) {
  SetupProfile p;
  p.name = name;
  p.hands[0] = {QStringLiteral("LeftForceps"), sim::Instrument::Forceps, QStringLiteral("LeftGrip"), 812.0, 96.5,
                Eigen::Vector3d(0.25, -1.5, 152.125), 0.083};
  p.hands[1] = {QStringLiteral("NeedleHolder"), sim::Instrument::NeedleHolder, {}, 0.0, 1.0,
                Eigen::Vector3d(1.0 / 3.0, 0.0, 140.0), std::nullopt};
  Eigen::Affine3d t = Eigen::Translation3d(10.0, -20.5, 3.0) * Eigen::AngleAxisd(0.4, Eigen::Vector3d(0, 0.6, 0.8));
  p.trackerToScene = t.matrix();
  p.freMm = 0.31;
  p.treMm = 0.57;
  p.handPerScene = 4.0;
  p.scalingAnchor = Eigen::Vector3d(1, 2, 3);
  p.latencyS = 0.034;
  p.calibratedAt = QDateTime(QDate(2026, 11, 22), QTime(17, 5, 9, 250), Qt::UTC);
  p.calibratedBy = QStringLiteral("J. Técnico");
  return p;
}

TEST(SetupProfiles, SaveListLoadReplaceRemoveOnARealFile) {
  QTemporaryDir dir;
  const QString path = dir.filePath(QStringLiteral("history.sqlite"));
  qint64 benchId = 0;
  {
    HistoryDatabase db;
    ASSERT_TRUE(db.open(path).ok());
    SetupProfileStore store(db);
    EXPECT_TRUE(store.list().isEmpty());
    const std::optional<qint64> id = store.save(sampleProfile(QStringLiteral("Bench 1")));
    ASSERT_TRUE(id) << store.lastError().toStdString();
    benchId = *id;
    SetupProfile second = sampleProfile(QStringLiteral("Bench 2"));
    second.calibratedAt = second.calibratedAt.addDays(1);
    second.freMm.reset();
    ASSERT_TRUE(store.save(second));
  }

  // a fresh connection to the same file sees both
  HistoryDatabase db;
  ASSERT_TRUE(db.open(path).ok());
  SetupProfileStore store(db);
  const QList<SetupProfileSummary> list = store.list();
  ASSERT_EQ(list.size(), 2);
  EXPECT_EQ(list[0].name, QStringLiteral("Bench 2"));  // newest first
  EXPECT_FALSE(list[0].freMm.has_value());
  EXPECT_EQ(list[1].id, benchId);
  EXPECT_DOUBLE_EQ(*list[1].freMm, 0.31);
  EXPECT_EQ(list[1].calibratedBy, QStringLiteral("J. Técnico"));

  const std::optional<SetupProfile> loaded = store.load(benchId);
  ASSERT_TRUE(loaded) << store.lastError().toStdString();
  EXPECT_EQ(loaded->id, benchId);
  EXPECT_TRUE(loaded->sameContent(sampleProfile(QStringLiteral("Bench 1"))));

  // saving under the same name replaces, keeping the id
  SetupProfile changed = *loaded;
  changed.hands[0].tipOffset.z() = 150.0;
  EXPECT_EQ(store.save(changed), benchId);
  EXPECT_EQ(store.list().size(), 2);
  EXPECT_DOUBLE_EQ(store.loadByName(QStringLiteral("Bench 1"))->hands[0].tipOffset.z(), 150.0);

  EXPECT_TRUE(store.remove(benchId));
  EXPECT_FALSE(store.load(benchId));
  EXPECT_FALSE(store.remove(benchId));
  EXPECT_EQ(store.list().size(), 1);
}

TEST(SetupProfiles, AProfileWithoutErrorsOrCalibratorIsStored) {
  QTemporaryDir dir;
  HistoryDatabase db;
  ASSERT_TRUE(db.open(dir.filePath(QStringLiteral("history.sqlite"))).ok());
  SetupProfileStore store(db);
  SetupProfile p;
  p.name = QStringLiteral("Fresh");
  p.calibratedAt = QDateTime(QDate(2026, 1, 2), QTime(3, 4, 5), Qt::UTC);
  const std::optional<qint64> id = store.save(p);
  ASSERT_TRUE(id) << store.lastError().toStdString();
  const std::optional<SetupProfile> back = store.load(*id);
  ASSERT_TRUE(back);
  EXPECT_TRUE(back->sameContent(p));
  EXPECT_FALSE(store.list().front().freMm);
}

TEST(SetupProfiles, JsonRoundTripKeepsEveryBit) {
  const SetupProfile p = sampleProfile(QStringLiteral("Bench 1"));
  const auto back = importProfileJson(exportProfileJson(p));
  ASSERT_TRUE(std::holds_alternative<SetupProfile>(back)) << std::get<ProfileJsonError>(back).field.toStdString();
  EXPECT_TRUE(std::get<SetupProfile>(back).sameContent(p));
}

// the exported document with one field changed
QByteArray edited(const std::function<void(QJsonObject&)>& edit) {
  QJsonObject root = QJsonDocument::fromJson(exportProfileJson(sampleProfile(QStringLiteral("Bench")))).object();
  edit(root);
  return QJsonDocument(root).toJson();
}

void expectRefused(const QByteArray& json, ProfileJsonProblem problem, const char* field) {
  const auto r = importProfileJson(json);
  ASSERT_TRUE(std::holds_alternative<ProfileJsonError>(r)) << field;
  EXPECT_EQ(std::get<ProfileJsonError>(r).problem, problem) << field;
  EXPECT_EQ(std::get<ProfileJsonError>(r).field.toStdString(), field);
}

TEST(SetupProfiles, MalformedJsonIsRefusedWithTheFieldNamed) {
  EXPECT_EQ(std::get<ProfileJsonError>(importProfileJson("not json")).problem, ProfileJsonProblem::NotJson);
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("format"), QStringLiteral("other")); }),
                ProfileJsonProblem::WrongFormat, "format");
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("version"), 9); }), ProfileJsonProblem::WrongFormat,
                "version");
  expectRefused(edited([](QJsonObject& o) { o.remove(QStringLiteral("name")); }), ProfileJsonProblem::Missing, "name");
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("name"), QStringLiteral("  ")); }),
                ProfileJsonProblem::OutOfRange, "name");
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("calibrated_at"), QStringLiteral("yesterday")); }),
                ProfileJsonProblem::OutOfRange, "calibrated_at");
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("hands"), QJsonArray{}); }),
                ProfileJsonProblem::WrongType, "hands");
  expectRefused(edited([](QJsonObject& o) {
                  QJsonArray hands = o.value(QStringLiteral("hands")).toArray();
                  QJsonObject h = hands.at(1).toObject();
                  h.insert(QStringLiteral("tip_offset_mm"), QJsonArray{1, 2});
                  hands.replace(1, h);
                  o.insert(QStringLiteral("hands"), hands);
                }),
                ProfileJsonProblem::WrongType, "hands[1].tip_offset_mm");
  expectRefused(edited([](QJsonObject& o) {
                  QJsonArray hands = o.value(QStringLiteral("hands")).toArray();
                  QJsonObject h = hands.at(0).toObject();
                  h.insert(QStringLiteral("instrument"), QStringLiteral("chopsticks"));
                  hands.replace(0, h);
                  o.insert(QStringLiteral("hands"), hands);
                }),
                ProfileJsonProblem::OutOfRange, "hands[0].instrument");
  expectRefused(edited([](QJsonObject& o) {
                  QJsonArray hands = o.value(QStringLiteral("hands")).toArray();
                  QJsonObject h = hands.at(0).toObject();
                  h.remove(QStringLiteral("device"));
                  hands.replace(0, h);
                  o.insert(QStringLiteral("hands"), hands);
                }),
                ProfileJsonProblem::Missing, "hands[0].device");
  expectRefused(edited([](QJsonObject& o) {
                  QJsonArray m = o.value(QStringLiteral("tracker_to_scene")).toArray();
                  m.replace(1, 0.5);  // a shear: not a similarity
                  o.insert(QStringLiteral("tracker_to_scene"), m);
                }),
                ProfileJsonProblem::OutOfRange, "tracker_to_scene");
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("fre_mm"), -1.0); }), ProfileJsonProblem::OutOfRange,
                "fre_mm");
  expectRefused(edited([](QJsonObject& o) { o.insert(QStringLiteral("latency_s"), QStringLiteral("fast")); }),
                ProfileJsonProblem::WrongType, "latency_s");
  expectRefused(edited([](QJsonObject& o) {
                  o.insert(QStringLiteral("motion_scaling"),
                           QJsonObject{{QStringLiteral("hand_per_scene"), 0.0},
                                       {QStringLiteral("anchor_mm"), QJsonArray{0, 0, 0}}});
                }),
                ProfileJsonProblem::OutOfRange, "motion_scaling.hand_per_scene");
}

}  // namespace
}  // namespace microsim::assessment
