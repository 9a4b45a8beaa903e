// `microsim-cli track --igtl HOST:PORT [--duration S] [--json OUT] [--record FILE] [--once]
// [--max-speed MM_S]`: connects to an OpenIGTLink server, records what arrives for S
// seconds (or, with --once, until the server closes the link), and reports per device the
// accepted poses, the last one and the rate, and the refused messages by reason. --record
// writes every accepted pose and channel value, in arrival order, as a tracker stream
// (tracking/pose_stream.h) that ReplaySource and `calibrate pivot` read; each sample is
// flushed as it arrives, so a killed `track` leaves every complete sample, and a write
// that fails (disk full) stops the recording with exit code 1.
//
// JSON:
//   {"host": "127.0.0.1", "port": 18944, "connections": 1,
//    "devices": {"Stylus": {"received": 100, "last": [16 numbers, 4 by 4 row-major, mm],
//                           "rate_hz": 100.0}},
//    "channels": {"Grip": {"received": 10, "last": 0.5}},
//    "rejected": {"count": 3, "reasons": {"bad_crc": 1, "too_fast": 2, ...every reason...}}}
// rate_hz = (received − 1) / (last time − first time), from the messages' timestamps.
#include "cli/command_line.h"
#include "cli/commands.h"
#include "cli/output_file.h"

#include "tracking/igtl_client.h"
#include "tracking/pose_stream.h"

#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <map>

namespace microsim::cli {

namespace {

using tracking::ChannelValue;
using tracking::RawPose;

struct DeviceRecord {
  std::uint64_t received = 0;
  Eigen::Matrix4d last = Eigen::Matrix4d::Identity();
  double firstTime = 0.0;  ///< s, source clock
  double lastTime = 0.0;   ///< s, source clock

  double rateHz() const {
    const double span = lastTime - firstTime;
    return received >= 2 && span > 0.0 ? static_cast<double>(received - 1) / span : 0.0;
  }
};

struct ChannelRecord {
  std::uint64_t received = 0;
  double last = 0.0;
};

QJsonArray rowMajor(const Eigen::Matrix4d& m) {
  QJsonArray a;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) a.append(m(r, c));
  return a;
}

struct TrackOptions {
  QCommandLineOption igtl{QStringLiteral("igtl"),
                          Cli::tr("OpenIGTLink server to read, HOST:PORT (port 18944 by default)."),
                          QStringLiteral("host:port")};
  QCommandLineOption duration{QStringLiteral("duration"), Cli::tr("Record for <seconds> (default 10)."),
                              QStringLiteral("seconds"), QStringLiteral("10")};
  QCommandLineOption json{QStringLiteral("json"), Cli::tr("Write the record as JSON to <file>."), QStringLiteral("file")};
  QCommandLineOption record{QStringLiteral("record"),
                            Cli::tr("Write every accepted pose and channel value as a tracker stream to <file>."),
                            QStringLiteral("file")};
  QCommandLineOption once{QStringLiteral("once"), Cli::tr("Stop when the server closes the link (no reconnection).")};
  QCommandLineOption maxSpeed{QStringLiteral("max-speed"), Cli::tr("Refuse poses moving faster than <mm/s> (default 2000)."),
                              QStringLiteral("mm/s"), QStringLiteral("2000")};

  QString usage() const {
    return Cli::tr("Usage: microsim-cli track --igtl HOST:PORT [--duration S] [--json FILE] [--record FILE] "
                   "[--once] [--max-speed MM_S]");
  }
  void declare(CommandLine& line) const { line.addOptions({igtl, duration, json, record, once, maxSpeed}); }
};

// what the command line asks for, checked
struct TrackRequest {
  tracking::IgtlClientConfig link;
  double seconds = 10.0;
  QString record;  ///< the tracker stream file; empty: none
  QString json;
};

std::optional<TrackRequest> readTrackRequest(const CommandLine& line, const TrackOptions& o) {
  TrackRequest r;
  if (!line.isSet(o.igtl) || !tracking::parseHostPort(line.value(o.igtl), r.link.host, r.link.port)) {
    line.usageError(Cli::tr("give the server as --igtl HOST:PORT"));
    return std::nullopt;
  }
  bool okDuration = false, okSpeed = false;
  r.seconds = line.value(o.duration).toDouble(&okDuration);
  r.link.limits.maxSpeed = line.value(o.maxSpeed).toDouble(&okSpeed);
  if (!okDuration || !(r.seconds > 0.0) || !okSpeed || !(r.link.limits.maxSpeed > 0.0)) {
    line.usageError(Cli::tr("--duration and --max-speed take positive numbers"));
    return std::nullopt;
  }
  r.link.reconnect = !line.isSet(o.once);
  r.record = line.value(o.record);
  r.json = line.value(o.json);
  return r;
}

// what arrived: per device and channel, and the link's own count of connections and refusals
struct TrackRecord {
  std::map<std::string, DeviceRecord> devices;
  std::map<std::string, ChannelRecord> channels;
  tracking::TrackerStatus status;
  bool writeFailed = false;  ///< the stream file stopped taking samples (disk full)
};

// records every accepted pose and channel value on this thread until the time is up (or,
// without reconnection, the link goes down, or the stream file fails)
TrackRecord recordLink(const TrackRequest& request, tracking::PoseStreamWriter& writer) {
  TrackRecord rec;
  QEventLoop loop;
  const auto keep = [&writer, &rec, &loop](const tracking::StreamSample& sample) {
    if (!writer.isOpen() || rec.writeFailed) return;
    rec.writeFailed = !writer.append(sample).ok();
    if (rec.writeFailed) loop.quit();
  };
  QObject receiver;
  tracking::IgtlClient client(request.link);
  QObject::connect(&client, &tracking::TrackerSource::poseAccepted, &receiver, [&rec, &keep](const RawPose& pose) {
    keep(pose);
    DeviceRecord& d = rec.devices[pose.device];
    if (d.received == 0) d.firstTime = pose.time;
    ++d.received;
    d.last = pose.matrix;
    d.lastTime = pose.time;
  });
  QObject::connect(&client, &tracking::TrackerSource::channelAccepted, &receiver, [&rec, &keep](const ChannelValue& v) {
    keep(v);
    ChannelRecord& c = rec.channels[v.channel];
    ++c.received;
    c.last = v.value;
  });
  if (!request.link.reconnect)
    QObject::connect(&client, &tracking::TrackerSource::linkDown, &receiver, [&loop] { loop.quit(); });
  QTimer::singleShot(static_cast<int>(request.seconds * 1000.0), &receiver, [&loop] { loop.quit(); });
  client.start();
  loop.exec();
  client.stop();
  // signals queued before stop() returned
  QCoreApplication::sendPostedEvents(&receiver);
  rec.status = client.status();
  return rec;
}

void printTrackRecord(QTextStream& out, const TrackRequest& request, const TrackRecord& rec) {
  out << Cli::tr("%1 connection(s) to %2:%3").arg(rec.status.connections).arg(request.link.host).arg(request.link.port)
      << '\n';
  out << Cli::tr("device              received   rate (Hz)   last position (mm)") << '\n';
  for (const auto& [name, d] : rec.devices) {
    out << QString::fromStdString(name).leftJustified(20) << QString::number(d.received).rightJustified(8)
        << QString::number(d.rateHz(), 'f', 1).rightJustified(12) << "   " << d.last(0, 3) << ' ' << d.last(1, 3) << ' '
        << d.last(2, 3) << '\n';
  }
  for (const auto& [name, c] : rec.channels)
    out << QString::fromStdString(name).leftJustified(20) << QString::number(c.received).rightJustified(8)
        << "            " << c.last << '\n';
  out << Cli::tr("rejected: %1").arg(rec.status.rejected.total()) << '\n';
  for (int r = 0; r < tracking::kRejectionCount; ++r) {
    const auto reason = static_cast<tracking::Rejection>(r);
    if (rec.status.rejected[reason] > 0)
      out << "  " << QString::fromLatin1(tracking::rejectionKey(reason)).leftJustified(18) << rec.status.rejected[reason]
          << '\n';
  }
}

QJsonDocument trackRecordJson(const TrackRequest& request, const TrackRecord& rec) {
  QJsonObject devs;
  for (const auto& [name, d] : rec.devices)
    devs.insert(QString::fromStdString(name), QJsonObject{{QStringLiteral("received"), static_cast<qint64>(d.received)},
                                                          {QStringLiteral("last"), rowMajor(d.last)},
                                                          {QStringLiteral("rate_hz"), d.rateHz()}});
  QJsonObject chans;
  for (const auto& [name, c] : rec.channels)
    chans.insert(QString::fromStdString(name), QJsonObject{{QStringLiteral("received"), static_cast<qint64>(c.received)},
                                                           {QStringLiteral("last"), c.last}});
  QJsonObject reasons;
  for (int r = 0; r < tracking::kRejectionCount; ++r) {
    const auto reason = static_cast<tracking::Rejection>(r);
    reasons.insert(QLatin1String(tracking::rejectionKey(reason)), static_cast<qint64>(rec.status.rejected[reason]));
  }
  const QJsonObject rejected{{QStringLiteral("count"), static_cast<qint64>(rec.status.rejected.total())},
                             {QStringLiteral("reasons"), reasons}};
  return QJsonDocument(QJsonObject{{QStringLiteral("host"), request.link.host},
                                   {QStringLiteral("port"), request.link.port},
                                   {QStringLiteral("connections"), static_cast<qint64>(rec.status.connections)},
                                   {QStringLiteral("devices"), devs},
                                   {QStringLiteral("channels"), chans},
                                   {QStringLiteral("rejected"), rejected}});
}

// load → run → report
int recordTracker(const CommandLine& line, const TrackOptions& options) {
  const std::optional<TrackRequest> request = readTrackRequest(line, options);
  if (!request) return kExitUsage;

  // load: the stream file before the link, so that a bad path fails at once
  tracking::PoseStreamWriter writer;
  const auto cannotRecord = [&] { return line.failure(Cli::tr("cannot write %1").arg(request->record)); };
  if (!request->record.isEmpty() && !writer.open(request->record).ok()) return cannotRecord();

  // run
  const TrackRecord rec = recordLink(*request, writer);
  if (rec.status.connections == 0) {
    if (writer.isOpen()) writer.finish();
    return line.failure(Cli::tr("could not connect to %1:%2: %3")
                            .arg(request->link.host)
                            .arg(request->link.port)
                            .arg(rec.status.lastError));
  }

  // report: the table, the stream file's end, the JSON
  printTrackRecord(line.io().out, *request, rec);
  if (rec.writeFailed || (writer.isOpen() && !writer.finish().ok())) return cannotRecord();
  if (request->json.isEmpty()) return kExitOk;
  return writeCommandOutput(line, request->json, trackRecordJson(*request, rec).toJson());
}

}  // namespace

int runTrack(const QStringList& args, Streams& io) {
  return runCommand(QStringLiteral("track"), args, io, &recordTracker);
}

}  // namespace microsim::cli
