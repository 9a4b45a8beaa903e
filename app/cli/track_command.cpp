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
#include "cli/commands.h"
#include "cli/output_file.h"

#include "tracking/igtl_client.h"
#include "tracking/pose_stream.h"

#include <QCommandLineParser>
#include <QEventLoop>
#include <QFile>
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

}  // namespace

int runTrack(const QStringList& args, Streams& io) {
  QCommandLineParser parser;
  const QCommandLineOption igtl(QStringLiteral("igtl"), Cli::tr("OpenIGTLink server to read, HOST:PORT (port 18944 by default)."),
                                QStringLiteral("host:port"));
  const QCommandLineOption duration(QStringLiteral("duration"), Cli::tr("Record for <seconds> (default 10)."),
                                    QStringLiteral("seconds"), QStringLiteral("10"));
  const QCommandLineOption json(QStringLiteral("json"), Cli::tr("Write the record as JSON to <file>."), QStringLiteral("file"));
  const QCommandLineOption record(QStringLiteral("record"),
                                  Cli::tr("Write every accepted pose and channel value as a tracker stream to <file>."),
                                  QStringLiteral("file"));
  const QCommandLineOption once(QStringLiteral("once"), Cli::tr("Stop when the server closes the link (no reconnection)."));
  const QCommandLineOption maxSpeed(QStringLiteral("max-speed"), Cli::tr("Refuse poses moving faster than <mm/s> (default 2000)."),
                                    QStringLiteral("mm/s"), QStringLiteral("2000"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")}, Cli::tr("Show this help."));
  parser.addOptions({igtl, duration, json, record, once, maxSpeed, help});
  if (!parser.parse(QStringList{QStringLiteral("track")} + args)) {
    io.err << "microsim-cli track: " << parser.errorText() << '\n';
    return kExitUsage;
  }
  if (parser.isSet(help)) {
    io.out << Cli::tr("Usage: microsim-cli track --igtl HOST:PORT [--duration S] [--json FILE] [--record FILE] [--once] [--max-speed MM_S]")
           << "\n\n"
           << parser.helpText().section(QLatin1Char('\n'), 2);
    return kExitOk;
  }

  // the link and its limits
  tracking::IgtlClientConfig config;
  if (!parser.isSet(igtl) || !tracking::parseHostPort(parser.value(igtl), config.host, config.port)) {
    io.err << Cli::tr("microsim-cli track: give the server as --igtl HOST:PORT") << '\n';
    return kExitUsage;
  }
  bool okDuration = false, okSpeed = false;
  const double seconds = parser.value(duration).toDouble(&okDuration);
  config.limits.maxSpeed = parser.value(maxSpeed).toDouble(&okSpeed);
  if (!okDuration || !(seconds > 0.0) || !okSpeed || !(config.limits.maxSpeed > 0.0)) {
    io.err << Cli::tr("microsim-cli track: --duration and --max-speed take positive numbers") << '\n';
    return kExitUsage;
  }
  config.reconnect = !parser.isSet(once);

  // the stream file before the link, so that a bad path fails at once
  tracking::PoseStreamWriter writer;
  if (parser.isSet(record) && !writer.open(parser.value(record)).ok()) {
    io.err << Cli::tr("microsim-cli track: cannot write %1").arg(parser.value(record)) << '\n';
    return kExitFailure;
  }
  QEventLoop loop;
  bool writeFailed = false;
  const auto keep = [&writer, &writeFailed, &loop](const tracking::StreamSample& sample) {
    if (!writer.isOpen() || writeFailed) return;
    writeFailed = !writer.append(sample).ok();
    if (writeFailed) loop.quit();
  };

  // record every accepted pose and channel value on this thread
  std::map<std::string, DeviceRecord> devices;
  std::map<std::string, ChannelRecord> channels;
  QObject receiver;
  tracking::IgtlClient client(config);
  QObject::connect(&client, &tracking::TrackerSource::poseAccepted, &receiver, [&devices, &keep](const RawPose& pose) {
    keep(pose);
    DeviceRecord& d = devices[pose.device];
    if (d.received == 0) d.firstTime = pose.time;
    ++d.received;
    d.last = pose.matrix;
    d.lastTime = pose.time;
  });
  QObject::connect(&client, &tracking::TrackerSource::channelAccepted, &receiver, [&channels, &keep](const ChannelValue& v) {
    keep(v);
    ChannelRecord& c = channels[v.channel];
    ++c.received;
    c.last = v.value;
  });
  if (parser.isSet(once))
    QObject::connect(&client, &tracking::TrackerSource::linkDown, &receiver, [&loop] { loop.quit(); });
  QTimer::singleShot(static_cast<int>(seconds * 1000.0), &receiver, [&loop] { loop.quit(); });
  client.start();
  loop.exec();
  client.stop();
  // signals queued before stop() returned
  QCoreApplication::sendPostedEvents(&receiver);
  const tracking::TrackerStatus status = client.status();

  if (status.connections == 0) {
    if (writer.isOpen()) writer.finish();
    io.err << Cli::tr("microsim-cli track: could not connect to %1:%2: %3")
                  .arg(config.host)
                  .arg(config.port)
                  .arg(status.lastError)
           << '\n';
    return kExitFailure;
  }

  // the table
  io.out << Cli::tr("%1 connection(s) to %2:%3").arg(status.connections).arg(config.host).arg(config.port) << '\n';
  io.out << Cli::tr("device              received   rate (Hz)   last position (mm)") << '\n';
  for (const auto& [name, d] : devices) {
    io.out << QString::fromStdString(name).leftJustified(20) << QString::number(d.received).rightJustified(8)
           << QString::number(d.rateHz(), 'f', 1).rightJustified(12) << "   " << d.last(0, 3) << ' ' << d.last(1, 3)
           << ' ' << d.last(2, 3) << '\n';
  }
  for (const auto& [name, c] : channels)
    io.out << QString::fromStdString(name).leftJustified(20) << QString::number(c.received).rightJustified(8)
           << "            " << c.last << '\n';
  io.out << Cli::tr("rejected: %1").arg(status.rejected.total()) << '\n';
  for (int r = 0; r < tracking::kRejectionCount; ++r) {
    const auto reason = static_cast<tracking::Rejection>(r);
    if (status.rejected[reason] > 0)
      io.out << "  " << QString::fromLatin1(tracking::rejectionKey(reason)).leftJustified(18) << status.rejected[reason] << '\n';
  }

  if (writeFailed || (writer.isOpen() && !writer.finish().ok())) {
    io.err << Cli::tr("microsim-cli track: cannot write %1").arg(parser.value(record)) << '\n';
    return kExitFailure;
  }

  // the JSON
  if (parser.isSet(json)) {
    QJsonObject devs;
    for (const auto& [name, d] : devices)
      devs.insert(QString::fromStdString(name),
                  QJsonObject{{QStringLiteral("received"), static_cast<qint64>(d.received)},
                              {QStringLiteral("last"), rowMajor(d.last)},
                              {QStringLiteral("rate_hz"), d.rateHz()}});
    QJsonObject chans;
    for (const auto& [name, c] : channels)
      chans.insert(QString::fromStdString(name), QJsonObject{{QStringLiteral("received"), static_cast<qint64>(c.received)},
                                                             {QStringLiteral("last"), c.last}});
    QJsonObject reasons;
    for (int r = 0; r < tracking::kRejectionCount; ++r) {
      const auto reason = static_cast<tracking::Rejection>(r);
      reasons.insert(QLatin1String(tracking::rejectionKey(reason)), static_cast<qint64>(status.rejected[reason]));
    }
    const QJsonObject root{
        {QStringLiteral("host"), config.host},
        {QStringLiteral("port"), config.port},
        {QStringLiteral("connections"), static_cast<qint64>(status.connections)},
        {QStringLiteral("devices"), devs},
        {QStringLiteral("channels"), chans},
        {QStringLiteral("rejected"), QJsonObject{{QStringLiteral("count"), static_cast<qint64>(status.rejected.total())},
                                                 {QStringLiteral("reasons"), reasons}}}};
    QString why;
    if (!writeOutputFile(parser.value(json), QJsonDocument(root).toJson(), why)) {
      io.err << Cli::tr("microsim-cli track: cannot write %1").arg(parser.value(json)) << '\n';
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace microsim::cli
