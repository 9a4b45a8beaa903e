// `microsim-cli calibrate pivot|register --input FILE [--json OUT]`: a calibration run
// headless on recorded data.
//
// pivot input:
//   {"poses": [[16 numbers: the tool → tracker 4 by 4 matrix, row-major, mm], ...],
//    "min_poses": 8, "min_spread_deg": 15, "max_rms_mm": 0.5}      (thresholds optional)
//   (the "last" arrays of `microsim-cli track --json` have this form), or a tracker stream
//   as `microsim-cli track --record` writes it (tracking/pose_stream.h): the poses of the
//   device named by --device (needed when the stream holds several). A stream cut short
//   (the recording process was killed) gives its complete samples and a warning.
// pivot output:
//   {"status": "ok", "tip_offset": [x, y, z] (tool frame, mm), "pivot": [x, y, z] (tracker
//    frame, mm), "rms_mm", "max_mm", "spread_deg", "poses"}
//
// register input:
//   {"fiducials": [{"tracker": [x, y, z], "scene": [x, y, z]}, ...],       (≥ 3, mm)
//    "check_points": [{"tracker": [...], "scene": [...]}, ...],           (optional, for TRE)
//    "scaling": false}                                                    (optional: similarity)
// register output:
//   {"status": "ok", "matrix": [16 numbers, tracker → scene, row-major], "scale",
//    "fre_rms_mm", "fre_max_mm", "fiducial_errors_mm": [...], "tre_rms_mm", "tre_max_mm",
//    "check_errors_mm": [...], "check_points"}
//
// Exit code 0 when the status is "ok", 1 otherwise (the JSON is still written), 2 on usage.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/output_file.h"

#include "calibration/pivot_calibration.h"
#include "calibration/registration.h"
#include "tracking/pose_stream.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <set>
#include <vector>

namespace microsim::cli {

namespace {

using calibration::PivotStatus;
using calibration::RegistrationStatus;

const char* pivotStatusKey(PivotStatus s) {
  switch (s) {
    case PivotStatus::Ok: return "ok";
    case PivotStatus::TooFewPoses: return "too_few_poses";
    case PivotStatus::NonFinite: return "non_finite";
    case PivotStatus::InsufficientSpread: return "insufficient_spread";
    case PivotStatus::RmsAboveThreshold: return "rms_above_threshold";
  }
  return "unknown";
}

const char* registrationStatusKey(RegistrationStatus s) {
  switch (s) {
    case RegistrationStatus::Ok: return "ok";
    case RegistrationStatus::TooFewFiducials: return "too_few_fiducials";
    case RegistrationStatus::SizeMismatch: return "size_mismatch";
    case RegistrationStatus::NonFinite: return "non_finite";
    case RegistrationStatus::Collinear: return "collinear";
  }
  return "unknown";
}

QJsonArray toJson(const Eigen::Vector3d& v) { return QJsonArray{v.x(), v.y(), v.z()}; }

QJsonArray toJson(const std::vector<double>& v) {
  QJsonArray a;
  for (double x : v) a.append(x);
  return a;
}

bool readVector3(const QJsonValue& value, Eigen::Vector3d& out) {
  const QJsonArray a = value.toArray();
  if (a.size() != 3) return false;
  for (int i = 0; i < 3; ++i) {
    if (!a.at(i).isDouble()) return false;
    out(i) = a.at(i).toDouble();
  }
  return true;
}

// [{"tracker": [..], "scene": [..]}, ...] into two 3 by N matrices
bool readPairs(const QJsonArray& pairs, Eigen::Matrix3Xd& tracker, Eigen::Matrix3Xd& scene) {
  tracker.resize(3, pairs.size());
  scene.resize(3, pairs.size());
  for (qsizetype i = 0; i < pairs.size(); ++i) {
    const QJsonObject o = pairs.at(i).toObject();
    Eigen::Vector3d a, b;
    if (!readVector3(o.value(QStringLiteral("tracker")), a) || !readVector3(o.value(QStringLiteral("scene")), b)) return false;
    tracker.col(i) = a;
    scene.col(i) = b;
  }
  return true;
}

// the poses of one device of a decoded tracker stream (whole, or Truncated: its complete samples)
bool streamPoses(const tracking::PoseStream& stream, const tracking::PoseStreamStatus& status, const QString& device,
                 std::vector<Eigen::Isometry3d>& poses, QString& error) {
  if (!status.ok() && status.error != tracking::PoseStreamError::Truncated) {
    error = status.error == tracking::PoseStreamError::BadSample
                ? Cli::tr("sample %1 of the tracker stream: bad \"%2\"").arg(status.sample).arg(status.field)
                : Cli::tr("not a tracker stream this version reads");
    return false;
  }
  std::set<std::string> devices;
  for (const tracking::StreamSample& s : stream.samples)
    if (const auto* p = std::get_if<tracking::RawPose>(&s)) devices.insert(p->device);
  std::string chosen = device.toStdString();
  if (chosen.empty() && devices.size() == 1) chosen = *devices.begin();
  // a stream with no pose at all (cut right after its header) is "too few poses", below
  if (!devices.empty() && !devices.contains(chosen)) {
    QStringList names;
    for (const std::string& d : devices) names << QString::fromStdString(d);
    error = Cli::tr("choose the device with --device (the stream holds: %1)").arg(names.join(QStringLiteral(", ")));
    return false;
  }
  for (const tracking::StreamSample& s : stream.samples)
    if (const auto* p = std::get_if<tracking::RawPose>(&s); p != nullptr && p->device == chosen && p->hasRotation)
      poses.emplace_back(p->matrix);
  return true;
}

// `poses` holds those of a tracker stream, if the input was one; `in`'s own are appended
QJsonObject runPivot(const QJsonObject& in, std::vector<Eigen::Isometry3d> poses, int& exitCode, QString& error) {
  for (const QJsonValue& v : in.value(QStringLiteral("poses")).toArray()) {
    const QJsonArray a = v.toArray();
    if (a.size() != 16) {
      error = Cli::tr("each pose must be 16 numbers (a 4 by 4 matrix, row-major)");
      return {};
    }
    Eigen::Matrix4d m;
    for (int k = 0; k < 16; ++k) m(k / 4, k % 4) = a.at(k).toDouble();
    poses.emplace_back(m);
  }
  calibration::PivotOptions options;
  options.minPoses = in.value(QStringLiteral("min_poses")).toInt(options.minPoses);
  options.minSpreadDeg = in.value(QStringLiteral("min_spread_deg")).toDouble(options.minSpreadDeg);
  options.maxRms = in.value(QStringLiteral("max_rms_mm")).toDouble(options.maxRms);

  const calibration::PivotResult r = calibration::pivotCalibration(poses, options);
  exitCode = r.accepted() ? kExitOk : kExitFailure;
  return QJsonObject{{QStringLiteral("status"), QLatin1String(pivotStatusKey(r.status))},
                     {QStringLiteral("tip_offset"), toJson(r.tipOffset)},
                     {QStringLiteral("pivot"), toJson(r.pivot)},
                     {QStringLiteral("rms_mm"), r.rmsError},
                     {QStringLiteral("max_mm"), r.maxError},
                     {QStringLiteral("spread_deg"), r.spreadDeg},
                     {QStringLiteral("poses"), r.poseCount}};
}

QJsonObject runRegister(const QJsonObject& in, int& exitCode, QString& error) {
  Eigen::Matrix3Xd tracker, scene, checkTracker, checkScene;
  if (!readPairs(in.value(QStringLiteral("fiducials")).toArray(), tracker, scene) ||
      !readPairs(in.value(QStringLiteral("check_points")).toArray(), checkTracker, checkScene)) {
    error = Cli::tr("each fiducial and check point needs \"tracker\" and \"scene\" as [x, y, z]");
    return {};
  }
  const calibration::RegistrationResult r = calibration::registerPoints(
      tracker, scene, checkTracker, checkScene, in.value(QStringLiteral("scaling")).toBool(false));
  exitCode = r.ok() ? kExitOk : kExitFailure;
  QJsonArray matrix;
  for (int k = 0; k < 16; ++k) matrix.append(r.transform(k / 4, k % 4));
  return QJsonObject{{QStringLiteral("status"), QLatin1String(registrationStatusKey(r.status))},
                     {QStringLiteral("matrix"), matrix},
                     {QStringLiteral("scale"), r.scale},
                     {QStringLiteral("fre_rms_mm"), r.freRms},
                     {QStringLiteral("fre_max_mm"), r.freMax},
                     {QStringLiteral("fiducial_errors_mm"), toJson(r.fiducialErrors)},
                     {QStringLiteral("tre_rms_mm"), r.treRms},
                     {QStringLiteral("tre_max_mm"), r.treMax},
                     {QStringLiteral("check_errors_mm"), toJson(r.checkErrors)},
                     {QStringLiteral("check_points"), r.checkCount}};
}

// the input document: a JSON object, or for pivot a tracker stream, whole or cut short
// (a `track --record` that was killed leaves its complete samples and no end)
struct CalibrationInput {
  QJsonObject document;
  bool isStream = false;
  tracking::PoseStream stream;
  tracking::PoseStreamStatus streamStatus{tracking::PoseStreamError::NotJson, -1, {}};
};

std::optional<CalibrationInput> readCalibrationInput(const CommandLine& line, const QString& path, bool pivot) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) {
    line.failure(Cli::tr("cannot read %1").arg(path));
    return std::nullopt;
  }
  const QByteArray bytes = f.readAll();
  QJsonParseError parseError;
  const QJsonDocument doc = QJsonDocument::fromJson(bytes, &parseError);
  CalibrationInput in;
  // a stream's document has "samples"; one cut short is no JSON document at all
  in.isStream = pivot && (!doc.isObject() || doc.object().contains(QStringLiteral("samples")));
  if (in.isStream) in.streamStatus = tracking::decodePoseStream(bytes, in.stream);
  const bool cutShort = in.streamStatus.error == tracking::PoseStreamError::Truncated;
  if (!doc.isObject() && !cutShort) {
    line.failure(Cli::tr("%1 is not a JSON object: %2").arg(path, parseError.errorString()));
    return std::nullopt;
  }
  if (cutShort)
    line.warning(Cli::tr("%1 was cut short (the recording stopped before its end); "
                         "using its %n complete sample(s)",
                         nullptr, static_cast<int>(in.stream.samples.size()))
                     .arg(path));
  in.document = doc.object();
  return in;
}

// the result's fields, one a line
void printCalibrationResult(QTextStream& out, const QJsonObject& result) {
  for (auto it = result.begin(); it != result.end(); ++it) {
    const QJsonValue v = it.value();
    QString text;
    if (v.isArray()) {
      QStringList parts;
      for (const QJsonValue& x : v.toArray()) parts << QString::number(x.toDouble(), 'g', 8);
      text = parts.join(QLatin1Char(' '));
    } else if (v.isString()) {
      text = v.toString();
    } else {
      text = QString::number(v.toDouble(), 'g', 8);
    }
    out << it.key().leftJustified(20) << text << '\n';
  }
}

struct CalibrateOptions {
  QCommandLineOption input{QStringLiteral("input"), Cli::tr("Read the poses or points from the JSON <file>."),
                           QStringLiteral("file")};
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write the result as JSON to <file>."), QStringLiteral("file")};
  QCommandLineOption device{QStringLiteral("device"), Cli::tr("pivot on a tracker stream: the device to calibrate."),
                            QStringLiteral("name")};

  QString usage() const {
    return Cli::tr("Usage: microsim-cli calibrate pivot|register --input FILE [--device NAME] [--json FILE]");
  }
  void declare(CommandLine& line) const {
    line.addOptions({input, json, device});
    line.addWord(QStringLiteral("kind"), Cli::tr("pivot or register"));
  }
};

// load → run → report
int calibrateFromFile(const CommandLine& line, const CalibrateOptions& options) {
  const QString kind = line.words().value(0);
  if ((kind != QLatin1String("pivot") && kind != QLatin1String("register")) || !line.isSet(options.input))
    return line.usageError(Cli::tr("say pivot or register, and give --input FILE"));
  const bool pivot = kind == QLatin1String("pivot");

  // load
  const std::optional<CalibrationInput> in = readCalibrationInput(line, line.value(options.input), pivot);
  if (!in) return kExitFailure;

  // run
  int exitCode = kExitFailure;
  QString error;
  QJsonObject result;
  if (!pivot) {
    result = runRegister(in->document, exitCode, error);
  } else {
    std::vector<Eigen::Isometry3d> poses;
    if (!in->isStream || streamPoses(in->stream, in->streamStatus, line.value(options.device), poses, error))
      result = runPivot(in->document, std::move(poses), exitCode, error);
  }
  if (!error.isEmpty()) return line.failure(error);

  // report: the table, the JSON (written whatever the status)
  printCalibrationResult(line.io().out, result);
  if (line.isSet(options.json)) {
    const int written = writeCommandOutput(line, line.value(options.json), QJsonDocument(result).toJson());
    if (written != kExitOk) return written;
  }
  return exitCode;
}

}  // namespace

int runCalibrate(const QStringList& args, Streams& io) {
  return runCommand(QStringLiteral("calibrate"), args, io, &calibrateFromFile);
}

}  // namespace microsim::cli
