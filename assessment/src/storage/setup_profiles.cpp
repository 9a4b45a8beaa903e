#include "microsim/assessment/storage/setup_profiles.h"

#include <Eigen/LU>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSqlError>
#include <QSqlQuery>

#include <cmath>

namespace microsim::assessment {

namespace {

const QString kFormat = QStringLiteral("microsim-setup-profile");
constexpr int kVersion = 1;

struct Instruments {
  sim::Instrument instrument;
  const char* key;
};
constexpr Instruments kInstruments[] = {{sim::Instrument::None, "none"},
                                        {sim::Instrument::Forceps, "forceps"},
                                        {sim::Instrument::NeedleHolder, "needle_holder"},
                                        {sim::Instrument::Scalpel, "scalpel"},
                                        {sim::Instrument::Scissors, "scissors"}};

QJsonValue optionalNumber(const std::optional<double>& v) { return v ? QJsonValue(*v) : QJsonValue(QJsonValue::Null); }

QJsonArray vector3(const Eigen::Vector3d& v) { return QJsonArray{v.x(), v.y(), v.z()}; }

// reads fields of one object and remembers the first one at fault, by its path
class ProfileReader {
 public:
  ProfileReader(const QJsonObject& o, QString prefix, std::optional<ProfileJsonError>& error)
      : o_(o), prefix_(std::move(prefix)), error_(error) {}

  bool fail(ProfileJsonProblem p, const QString& key) {
    if (!error_) error_ = ProfileJsonError{p, prefix_ + key};
    return false;
  }
  QString path(const QString& key) const { return prefix_ + key; }

  bool string(const QString& key, QString& out, bool required = true) {
    const QJsonValue v = o_.value(key);
    if (v.isUndefined() && !required) return true;
    if (v.isUndefined()) return fail(ProfileJsonProblem::Missing, key);
    if (!v.isString()) return fail(ProfileJsonProblem::WrongType, key);
    out = v.toString();
    return true;
  }
  bool number(const QString& key, double& out) {
    const QJsonValue v = o_.value(key);
    if (v.isUndefined()) return fail(ProfileJsonProblem::Missing, key);
    if (!v.isDouble()) return fail(ProfileJsonProblem::WrongType, key);
    out = v.toDouble();
    return std::isfinite(out) || fail(ProfileJsonProblem::OutOfRange, key);
  }
  // absent or null: no value; otherwise a finite number ≥ 0
  bool error(const QString& key, std::optional<double>& out) {
    const QJsonValue v = o_.value(key);
    if (v.isUndefined() || v.isNull()) {
      out.reset();
      return true;
    }
    if (!v.isDouble()) return fail(ProfileJsonProblem::WrongType, key);
    const double x = v.toDouble();
    if (!std::isfinite(x) || x < 0.0) return fail(ProfileJsonProblem::OutOfRange, key);
    out = x;
    return true;
  }
  bool numbers(const QString& key, double* out, int n) {
    const QJsonValue v = o_.value(key);
    if (v.isUndefined()) return fail(ProfileJsonProblem::Missing, key);
    const QJsonArray a = v.toArray();
    if (!v.isArray() || a.size() != n) return fail(ProfileJsonProblem::WrongType, key);
    for (int i = 0; i < n; ++i) {
      if (!a.at(i).isDouble()) return fail(ProfileJsonProblem::WrongType, key);
      out[i] = a.at(i).toDouble();
      if (!std::isfinite(out[i])) return fail(ProfileJsonProblem::OutOfRange, key);
    }
    return true;
  }
  bool vector(const QString& key, Eigen::Vector3d& out) { return numbers(key, out.data(), 3); }
  bool object(const QString& key, QJsonObject& out) {
    const QJsonValue v = o_.value(key);
    if (v.isUndefined()) return fail(ProfileJsonProblem::Missing, key);
    if (!v.isObject()) return fail(ProfileJsonProblem::WrongType, key);
    out = v.toObject();
    return true;
  }

 private:
  const QJsonObject& o_;
  QString prefix_;
  std::optional<ProfileJsonError>& error_;
};

bool readHand(const QJsonObject& o, const QString& prefix, ProfileHand& hand, std::optional<ProfileJsonError>& error) {
  ProfileReader r(o, prefix, error);
  QString instrument;
  if (!r.string(QStringLiteral("device"), hand.device) || !r.string(QStringLiteral("instrument"), instrument)) return false;
  bool known = false;
  for (const Instruments& i : kInstruments) {
    if (instrument == QLatin1String(i.key)) {
      hand.instrument = i.instrument;
      known = true;
    }
  }
  if (!known) return r.fail(ProfileJsonProblem::OutOfRange, QStringLiteral("instrument"));
  return r.string(QStringLiteral("closure_channel"), hand.closureChannel, false) &&
         r.number(QStringLiteral("closure_open"), hand.closureOpen) &&
         r.number(QStringLiteral("closure_closed"), hand.closureClosed) &&
         r.vector(QStringLiteral("tip_offset_mm"), hand.tipOffset) &&
         r.error(QStringLiteral("pivot_rms_mm"), hand.pivotRmsMm);
}

// [sR t; 0 1] with R a rotation and s > 0, to float32-level round-off
bool isSimilarity(const Eigen::Matrix4d& m) {
  if ((m.row(3) - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-9) return false;
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  const double det = a.determinant();
  if (!(det > 0.0)) return false;
  const double s2 = std::cbrt(det) * std::cbrt(det);
  return ((a.transpose() * a) / s2 - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-4;
}

}  // namespace

bool SetupProfile::sameContent(const SetupProfile& o) const {
  return name == o.name && hands == o.hands && trackerToScene == o.trackerToScene && freMm == o.freMm &&
         treMm == o.treMm && handPerScene == o.handPerScene && scalingAnchor == o.scalingAnchor &&
         latencyS == o.latencyS && calibratedAt == o.calibratedAt && calibratedBy == o.calibratedBy;
}

QString instrumentKey(sim::Instrument instrument) {
  for (const Instruments& i : kInstruments)
    if (i.instrument == instrument) return QLatin1String(i.key);
  return QStringLiteral("none");
}

QByteArray exportProfileJson(const SetupProfile& p) {
  QJsonArray hands;
  for (const ProfileHand& h : p.hands)
    hands.append(QJsonObject{{QStringLiteral("device"), h.device},
                             {QStringLiteral("instrument"), instrumentKey(h.instrument)},
                             {QStringLiteral("closure_channel"), h.closureChannel},
                             {QStringLiteral("closure_open"), h.closureOpen},
                             {QStringLiteral("closure_closed"), h.closureClosed},
                             {QStringLiteral("tip_offset_mm"), vector3(h.tipOffset)},
                             {QStringLiteral("pivot_rms_mm"), optionalNumber(h.pivotRmsMm)}});
  QJsonArray matrix;
  for (int k = 0; k < 16; ++k) matrix.append(p.trackerToScene(k / 4, k % 4));
  const QJsonObject root{
      {QStringLiteral("format"), kFormat},
      {QStringLiteral("version"), kVersion},
      {QStringLiteral("name"), p.name},
      {QStringLiteral("calibrated_at"), p.calibratedAt.toUTC().toString(Qt::ISODateWithMs)},
      {QStringLiteral("calibrated_by"), p.calibratedBy},
      {QStringLiteral("hands"), hands},
      {QStringLiteral("tracker_to_scene"), matrix},
      {QStringLiteral("fre_mm"), optionalNumber(p.freMm)},
      {QStringLiteral("tre_mm"), optionalNumber(p.treMm)},
      {QStringLiteral("motion_scaling"), QJsonObject{{QStringLiteral("hand_per_scene"), p.handPerScene},
                                                     {QStringLiteral("anchor_mm"), vector3(p.scalingAnchor)}}},
      {QStringLiteral("latency_s"), optionalNumber(p.latencyS)}};
  return QJsonDocument(root).toJson(QJsonDocument::Indented);
}

std::variant<SetupProfile, ProfileJsonError> importProfileJson(const QByteArray& json) {
  const QJsonDocument doc = QJsonDocument::fromJson(json);
  if (!doc.isObject()) return ProfileJsonError{ProfileJsonProblem::NotJson, {}};
  const QJsonObject root = doc.object();
  if (root.value(QStringLiteral("format")).toString() != kFormat)
    return ProfileJsonError{ProfileJsonProblem::WrongFormat, QStringLiteral("format")};
  if (root.value(QStringLiteral("version")).toInt(0) != kVersion)
    return ProfileJsonError{ProfileJsonProblem::WrongFormat, QStringLiteral("version")};

  SetupProfile p;
  std::optional<ProfileJsonError> error;
  ProfileReader r(root, QString(), error);

  // who, when
  QString at;
  if (r.string(QStringLiteral("name"), p.name) && p.name.trimmed().isEmpty())
    r.fail(ProfileJsonProblem::OutOfRange, QStringLiteral("name"));
  if (r.string(QStringLiteral("calibrated_at"), at)) {
    p.calibratedAt = QDateTime::fromString(at, Qt::ISODateWithMs);
    if (!p.calibratedAt.isValid()) r.fail(ProfileJsonProblem::OutOfRange, QStringLiteral("calibrated_at"));
    p.calibratedAt = p.calibratedAt.toUTC();
  }
  r.string(QStringLiteral("calibrated_by"), p.calibratedBy, false);

  // the hands
  const QJsonValue hands = root.value(QStringLiteral("hands"));
  if (hands.isUndefined()) {
    r.fail(ProfileJsonProblem::Missing, QStringLiteral("hands"));
  } else if (!hands.isArray() || hands.toArray().size() != sim::kHandCount) {
    r.fail(ProfileJsonProblem::WrongType, QStringLiteral("hands"));
  } else {
    for (int h = 0; h < sim::kHandCount; ++h) {
      const QString prefix = QStringLiteral("hands[%1]").arg(h);
      const QJsonValue v = hands.toArray().at(h);
      if (!v.isObject())
        r.fail(ProfileJsonProblem::WrongType, prefix);
      else
        readHand(v.toObject(), prefix + QLatin1Char('.'), p.hands[h], error);
    }
  }

  // the calibration
  std::array<double, 16> m{};
  if (r.numbers(QStringLiteral("tracker_to_scene"), m.data(), 16)) {
    for (int k = 0; k < 16; ++k) p.trackerToScene(k / 4, k % 4) = m[static_cast<std::size_t>(k)];
    if (!isSimilarity(p.trackerToScene)) r.fail(ProfileJsonProblem::OutOfRange, QStringLiteral("tracker_to_scene"));
  }
  r.error(QStringLiteral("fre_mm"), p.freMm);
  r.error(QStringLiteral("tre_mm"), p.treMm);
  QJsonObject scaling;
  if (r.object(QStringLiteral("motion_scaling"), scaling)) {
    ProfileReader s(scaling, QStringLiteral("motion_scaling."), error);
    if (s.number(QStringLiteral("hand_per_scene"), p.handPerScene) && !(p.handPerScene > 0.0))
      s.fail(ProfileJsonProblem::OutOfRange, QStringLiteral("hand_per_scene"));
    s.vector(QStringLiteral("anchor_mm"), p.scalingAnchor);
  }
  r.error(QStringLiteral("latency_s"), p.latencyS);

  if (error) return *error;
  return p;
}

std::optional<qint64> SetupProfileStore::save(const SetupProfile& profile) {
  QSqlDatabase db = db_.connection();
  const QString now = QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs);
  const auto optional = [](const std::optional<double>& v) { return v ? QVariant(*v) : QVariant(QMetaType::fromType<double>()); };

  // update the profile of that name, or insert it; then read its id back (portable)
  QSqlQuery q(db);
  q.prepare(QStringLiteral(
      "UPDATE setup_profiles SET calibrated_by = ?, calibrated_at = ?, fre_mm = ?, tre_mm = ?, document = ?, "
      "updated_at = ? WHERE name = ?"));
  const QString document = QString::fromUtf8(exportProfileJson(profile));
  // an empty, not a null, string: a null QString binds as SQL NULL
  const QString by = profile.calibratedBy.isNull() ? QStringLiteral("") : profile.calibratedBy;
  const QString at = profile.calibratedAt.toUTC().toString(Qt::ISODateWithMs);
  for (const QVariant& v : {QVariant(by), QVariant(at), optional(profile.freMm),
                            optional(profile.treMm), QVariant(document), QVariant(now), QVariant(profile.name)})
    q.addBindValue(v);
  if (!q.exec()) {
    lastError_ = q.lastError().text();
    return std::nullopt;
  }
  if (q.numRowsAffected() == 0) {
    q.prepare(QStringLiteral(
        "INSERT INTO setup_profiles (name, calibrated_by, calibrated_at, fre_mm, tre_mm, document, updated_at) "
        "VALUES (?, ?, ?, ?, ?, ?, ?)"));
    for (const QVariant& v : {QVariant(profile.name), QVariant(by), QVariant(at),
                              optional(profile.freMm), optional(profile.treMm), QVariant(document), QVariant(now)})
      q.addBindValue(v);
    if (!q.exec()) {
      lastError_ = q.lastError().text();
      return std::nullopt;
    }
  }
  q.prepare(QStringLiteral("SELECT id FROM setup_profiles WHERE name = ?"));
  q.addBindValue(profile.name);
  if (!q.exec() || !q.next()) {
    lastError_ = q.lastError().text();
    return std::nullopt;
  }
  return q.value(0).toLongLong();
}

std::optional<SetupProfile> SetupProfileStore::loadWhere(const QString& column, const QVariant& value) {
  QSqlQuery q(db_.connection());
  q.prepare(QStringLiteral("SELECT id, document FROM setup_profiles WHERE %1 = ?").arg(column));
  q.addBindValue(value);
  if (!q.exec()) {
    lastError_ = q.lastError().text();
    return std::nullopt;
  }
  if (!q.next()) {
    lastError_.clear();
    return std::nullopt;
  }
  auto parsed = importProfileJson(q.value(1).toString().toUtf8());
  if (auto* e = std::get_if<ProfileJsonError>(&parsed)) {
    lastError_ = QStringLiteral("document: ") + e->field;
    return std::nullopt;
  }
  SetupProfile p = std::get<SetupProfile>(std::move(parsed));
  p.id = q.value(0).toLongLong();
  return p;
}

std::optional<SetupProfile> SetupProfileStore::load(qint64 id) { return loadWhere(QStringLiteral("id"), id); }

std::optional<SetupProfile> SetupProfileStore::loadByName(const QString& name) {
  return loadWhere(QStringLiteral("name"), name);
}

QList<SetupProfileSummary> SetupProfileStore::list() {
  QList<SetupProfileSummary> out;
  QSqlQuery q(db_.connection());
  if (!q.exec(QStringLiteral("SELECT id, name, calibrated_at, calibrated_by, fre_mm, tre_mm FROM setup_profiles "
                             "ORDER BY calibrated_at DESC, name"))) {
    lastError_ = q.lastError().text();
    return out;
  }
  const auto optional = [](const QVariant& v) { return v.isNull() ? std::nullopt : std::optional<double>(v.toDouble()); };
  while (q.next())
    out.push_back({q.value(0).toLongLong(), q.value(1).toString(),
                   QDateTime::fromString(q.value(2).toString(), Qt::ISODateWithMs), q.value(3).toString(),
                   optional(q.value(4)), optional(q.value(5))});
  return out;
}

bool SetupProfileStore::remove(qint64 id) {
  QSqlQuery q(db_.connection());
  q.prepare(QStringLiteral("DELETE FROM setup_profiles WHERE id = ?"));
  q.addBindValue(id);
  if (!q.exec()) {
    lastError_ = q.lastError().text();
    return false;
  }
  return q.numRowsAffected() > 0;
}

}  // namespace microsim::assessment
