#include "tracking/pose_stream.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace microsim::tracking {

namespace {

const QString kFormat = QStringLiteral("microsim-tracker-stream");
constexpr int kVersion = 1;
// the writer's first line; a file that starts with it and does not parse was cut short
const QByteArray kHeaderLine = QByteArrayLiteral(R"({"format":"microsim-tracker-stream","version":1,"samples":[)") + '\n';
const QByteArray kEndLine = QByteArrayLiteral("]}\n");

QJsonObject toJson(const RawPose& p) {
  QJsonArray m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m.append(p.matrix(r, c));
  QJsonObject o{{QStringLiteral("device"), QString::fromStdString(p.device)},
                {QStringLiteral("time"), p.time},
                {QStringLiteral("matrix"), m}};
  if (!p.hasRotation) o.insert(QStringLiteral("position_only"), true);
  return o;
}

QJsonObject toJson(const ChannelValue& v) {
  return QJsonObject{{QStringLiteral("channel"), QString::fromStdString(v.channel)},
                     {QStringLiteral("time"), v.time},
                     {QStringLiteral("value"), v.value}};
}

// one sample; on failure names the field at fault
bool readSample(const QJsonObject& o, StreamSample& out, QString& field) {
  field = QStringLiteral("time");
  if (!o.value(field).isDouble()) return false;
  const double time = o.value(field).toDouble();
  if (o.contains(QStringLiteral("device"))) {
    RawPose p;
    field = QStringLiteral("device");
    if (!o.value(field).isString()) return false;
    p.device = o.value(field).toString().toStdString();
    p.time = time;
    field = QStringLiteral("matrix");
    const QJsonArray m = o.value(field).toArray();
    if (m.size() != 16) return false;
    for (int k = 0; k < 16; ++k) {
      if (!m.at(k).isDouble()) return false;
      p.matrix(k / 4, k % 4) = m.at(k).toDouble();
    }
    p.hasRotation = !o.value(QStringLiteral("position_only")).toBool(false);
    out = p;
    return true;
  }
  field = QStringLiteral("channel");
  if (!o.value(field).isString()) return false;
  ChannelValue v;
  v.channel = o.value(field).toString().toStdString();
  v.time = time;
  field = QStringLiteral("value");
  if (!o.value(field).isDouble()) return false;
  v.value = o.value(field).toDouble();
  out = v;
  return true;
}

}  // namespace

double sampleTime(const StreamSample& sample) {
  return std::visit([](const auto& s) { return s.time; }, sample);
}

// one sample's line, without its line end
QByteArray sampleLine(const StreamSample& sample, bool first) {
  const QJsonObject o = std::visit([](const auto& x) { return toJson(x); }, sample);
  return (first ? QByteArray() : QByteArrayLiteral(",")) + QJsonDocument(o).toJson(QJsonDocument::Compact);
}

QByteArray encodePoseStream(const PoseStream& stream) {
  QByteArray bytes = kHeaderLine;
  bool first = true;
  for (const StreamSample& s : stream.samples) {
    bytes += sampleLine(s, first) + '\n';
    first = false;
  }
  return bytes + kEndLine;
}

PoseStreamStatus decodePoseStream(const QByteArray& json, PoseStream& out) {
  PoseStreamStatus status;
  QJsonDocument doc = QJsonDocument::fromJson(json);
  bool truncated = false;
  // a writer stopped mid-stream: keep the complete lines and close the array
  if (!doc.isObject() && json.startsWith(kHeaderLine)) {
    const qsizetype lastLineEnd = json.lastIndexOf('\n');
    QByteArray closed = json.left(lastLineEnd + 1);
    if (closed.endsWith(kEndLine)) closed.chop(kEndLine.size());
    doc = QJsonDocument::fromJson(closed + kEndLine);
    truncated = true;
  }
  if (!doc.isObject()) {
    status.error = PoseStreamError::NotJson;
    return status;
  }
  const QJsonObject root = doc.object();
  if (root.value(QStringLiteral("format")).toString() != kFormat ||
      root.value(QStringLiteral("version")).toInt(0) < 1 || root.value(QStringLiteral("version")).toInt(0) > kVersion) {
    status.error = PoseStreamError::WrongFormat;
    return status;
  }
  out.samples.clear();
  const QJsonArray samples = root.value(QStringLiteral("samples")).toArray();
  out.samples.reserve(static_cast<std::size_t>(samples.size()));
  for (qsizetype i = 0; i < samples.size(); ++i) {
    StreamSample s;
    if (!samples.at(i).isObject() || !readSample(samples.at(i).toObject(), s, status.field)) {
      if (!samples.at(i).isObject()) status.field.clear();
      status.error = PoseStreamError::BadSample;
      status.sample = static_cast<int>(i);
      return status;
    }
    out.samples.push_back(std::move(s));
  }
  status.field.clear();
  if (truncated) status.error = PoseStreamError::Truncated;
  return status;
}

PoseStreamStatus readPoseStream(const QString& path, PoseStream& out) {
  QFile f(path);
  if (!f.open(QIODevice::ReadOnly)) return {PoseStreamError::CannotOpen, -1, {}};
  return decodePoseStream(f.readAll(), out);
}

PoseStreamStatus writePoseStream(const QString& path, const PoseStream& stream) {
  PoseStreamWriter writer;
  PoseStreamStatus s = writer.open(path);
  for (std::size_t i = 0; s.ok() && i < stream.samples.size(); ++i) s = writer.append(stream.samples[i]);
  if (s.ok()) s = writer.finish();
  return s;
}

PoseStreamStatus PoseStreamWriter::open(const QString& path) {
  file_.close();
  file_.setFileName(path);
  first_ = true;
  if (!file_.open(QIODevice::WriteOnly | QIODevice::Truncate)) return {PoseStreamError::CannotOpen, -1, {}};
  return writeLine(kHeaderLine);
}

PoseStreamStatus PoseStreamWriter::append(const StreamSample& sample) {
  if (!file_.isOpen()) return {PoseStreamError::CannotWrite, -1, {}};
  PoseStreamStatus s = writeLine(sampleLine(sample, first_) + '\n');
  first_ = false;
  return s;
}

PoseStreamStatus PoseStreamWriter::finish() {
  if (!file_.isOpen()) return {PoseStreamError::CannotWrite, -1, {}};
  PoseStreamStatus s = writeLine(kEndLine);
  file_.close();
  if (s.ok() && file_.error() != QFileDevice::NoError) s = {PoseStreamError::CannotWrite, -1, {}};
  return s;
}

// QFile buffers: the flush is where a full disk shows, and what a killed process keeps
PoseStreamStatus PoseStreamWriter::writeLine(const QByteArray& line) {
  if (file_.write(line) != line.size() || !file_.flush()) {
    file_.close();
    return {PoseStreamError::CannotWrite, -1, {}};
  }
  return {};
}

}  // namespace microsim::tracking
