// `microsim-cli run --scene S [--input REC | --script stitch] [--record REC] [--frames N]
// [--realtime] [--json OUT]`: builds the scene, feeds it one InputFrame per fixed step (from
// a recording, from the scripted stitch, or idle hands), and prints the final state hash,
// the events and the per-stage step times (median, p99, max).
#include "cli/commands.h"
#include "cli/output_file.h"

#include "cli/recording_text.h"
#include "cli/spring_scene_input.h"
#include "microsim/sim/scene/recording.h"
#include "microsim/sim/scene/scene.h"
#include "microsim/sim/scene/stitch_script.h"

#include <QCommandLineParser>
#include <QFile>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace microsim::cli {

namespace {

const char* eventKey(sim::SceneEventKind k) {
  using K = sim::SceneEventKind;
  switch (k) {
    case K::GrabTissue:
      return "grab-tissue";
    case K::ReleaseTissue:
      return "release-tissue";
    case K::GripSuture:
      return "grip-suture";
    case K::ReleaseSuture:
      return "release-suture";
    case K::PierceEntry:
      return "pierce-entry";
    case K::PierceExit:
      return "pierce-exit";
    case K::Cut:
      return "cut";
    case K::SutureBreak:
      return "suture-break";
    case K::SuturePulledOut:
      return "suture-pulled-out";
    case K::PierceReleased:
      return "pierce-released";
    case K::InputRejected:
      return "input-rejected";
    case K::TissueOverStretch:
      return "tissue-overstretch";
    case K::TissueTear:
      return "tissue-tear";
    case K::GraspEmpty:
      return "grasp-empty";
  }
  return "";
}

QString eventText(const sim::SceneEvent& e) {
  using K = sim::SceneEventKind;
  switch (e.kind) {
    case K::GrabTissue:
      return Cli::tr("forceps grabs %n tissue node(s)", nullptr, e.count);
    case K::ReleaseTissue:
      return Cli::tr("forceps releases %n tissue node(s)", nullptr, e.count);
    case K::GripSuture:
      return Cli::tr("forceps grips the suture at node %1").arg(e.index);
    case K::ReleaseSuture:
      return Cli::tr("forceps lets go of the suture");
    case K::PierceEntry:
      return Cli::tr("needle enters a wall");
    case K::PierceExit:
      return Cli::tr("needle leaves a wall");
    case K::Cut:
      return Cli::tr("scalpel cuts %n link(s)", nullptr, e.count);
    case K::SutureBreak:
      return Cli::tr("suture breaks at link %1").arg(e.index);
    case K::SuturePulledOut:
      return Cli::tr("suture slips out of a pierce");
    case K::PierceReleased:
      return Cli::tr("needle leaves a pierce before the thread reaches it");
    case K::InputRejected:
      return Cli::tr("input frame rejected");
    case K::TissueOverStretch:
      return Cli::tr("tissue link %1 over-stretched (%2 %)").arg(e.index).arg(e.count / 10.0);
    case K::TissueTear:
      return Cli::tr("tissue tears: %n link(s) removed", nullptr, e.count);
    case K::GraspEmpty:
      return Cli::tr("forceps closes on nothing: nothing lies between its jaws");
  }
  return {};
}

// median, p99 and max of one stage's step times, ms
struct Spread {
  double median = 0.0;
  double p99 = 0.0;
  double max = 0.0;
};

Spread spread(std::vector<double> seconds) {
  Spread s;
  if (seconds.empty()) return s;
  std::sort(seconds.begin(), seconds.end());
  const auto at = [&](double q) {
    const std::size_t i = static_cast<std::size_t>(std::ceil(q * static_cast<double>(seconds.size()))) - 1;
    return 1e3 * seconds[std::min(i, seconds.size() - 1)];
  };
  s.median = at(0.5);
  s.p99 = at(0.99);
  s.max = 1e3 * seconds.back();
  return s;
}

QString hex(std::uint64_t h) { return QStringLiteral("%1").arg(h, 16, 16, QLatin1Char('0')); }

}  // namespace

int runRun(const QStringList& args, Streams& io) {
  QCommandLineParser parser;
  const QCommandLineOption scene(QStringLiteral("scene"), Cli::tr("The scene <file> to run."),
                                 QStringLiteral("file"));
  const QCommandLineOption input(QStringLiteral("input"),
                                 Cli::tr("Replay the input frames of the recording <file>."),
                                 QStringLiteral("file"));
  const QCommandLineOption script(QStringLiteral("script"),
                                  Cli::tr("Generate the input instead: 'stitch' (one scripted stitch)."),
                                  QStringLiteral("name"));
  const QCommandLineOption record(QStringLiteral("record"),
                                  Cli::tr("Record every input frame to <file>."), QStringLiteral("file"));
  const QCommandLineOption frames(QStringLiteral("frames"),
                                  Cli::tr("Run <n> steps (default: every input frame, else 100)."),
                                  QStringLiteral("n"));
  const QCommandLineOption realtime(QStringLiteral("realtime"),
                                    Cli::tr("Stop each tissue solve at the step budget (not reproducible)."));
  const QCommandLineOption json(QStringLiteral("json"),
                                Cli::tr("Write the hash, events and timings as JSON to <file>."),
                                QStringLiteral("file"));
  const QCommandLineOption help(QStringList{QStringLiteral("h"), QStringLiteral("help")},
                                Cli::tr("Show this help."));
  parser.addOptions({scene, input, script, record, frames, realtime, json, help});
  const QString prefix = QStringLiteral("microsim-cli run: ");
  if (!parser.parse(QStringList{QStringLiteral("run")} + args)) {
    io.err << prefix << parser.errorText() << '\n';
    return kExitUsage;
  }
  if (parser.isSet(help)) {
    io.out << Cli::tr("Usage: microsim-cli run --scene FILE [--input REC | --script stitch] "
                      "[--record REC] [--frames N] [--json OUT]")
           << "\n\n"
           << parser.helpText().section(QLatin1Char('\n'), 2);
    return kExitOk;
  }
  if (!parser.positionalArguments().isEmpty()) {
    io.err << prefix << Cli::tr("unexpected argument '%1'").arg(parser.positionalArguments().front()) << '\n';
    return kExitUsage;
  }
  if (!parser.isSet(scene)) {
    io.err << prefix << Cli::tr("--scene FILE is required") << '\n';
    return kExitUsage;
  }
  if (parser.isSet(input) && parser.isSet(script)) {
    io.err << prefix << Cli::tr("--input and --script exclude each other") << '\n';
    return kExitUsage;
  }
  if (parser.isSet(script) && parser.value(script) != QLatin1String("stitch")) {
    io.err << prefix << Cli::tr("unknown script '%1' (known: stitch)").arg(parser.value(script)) << '\n';
    return kExitUsage;
  }
  long long frameLimit = -1;
  if (parser.isSet(frames)) {
    bool ok = false;
    frameLimit = parser.value(frames).toLongLong(&ok);
    if (!ok || frameLimit < 0) {
      io.err << prefix << Cli::tr("--frames wants a whole number ≥ 0, not '%1'").arg(parser.value(frames)) << '\n';
      return kExitUsage;
    }
  }

  // the scene, then the frames it is fed
  sim::SceneDefLoad load = sim::loadSceneDef(parser.value(scene).toStdString());
  if (auto* e = std::get_if<sim::SceneError>(&load)) {
    io.err << prefix << describeSceneError(*e) << '\n';
    return kExitFailure;
  }
  sim::SceneDef def = std::get<sim::SceneDef>(std::move(load));
  sim::Recording frameSource;
  if (parser.isSet(input)) {
    const sim::RecordingStatus status = sim::readRecording(parser.value(input).toStdString(), frameSource);
    if (status.error == sim::RecordingError::Truncated) {
      io.err << prefix << parser.value(input) << ": " << recordingErrorText(status.error) << "; "
             << Cli::tr("replaying its %n complete frame(s)", nullptr, static_cast<int>(frameSource.frames.size()))
             << '\n';
    } else if (!status.ok()) {
      io.err << prefix << parser.value(input) << ": " << recordingErrorText(status.error) << ' '
             << Cli::tr("(at byte %1)").arg(status.offset) << '\n';
      return kExitFailure;
    }
  } else if (parser.isSet(script)) {
    frameSource = sim::scriptedStitch(def);
    if (frameSource.frames.empty()) {
      io.err << prefix
             << Cli::tr("the stitch script needs a severed vessel, a curved needle and two forceps")
             << '\n';
      return kExitFailure;
    }
  }
  std::vector<sim::InputFrame> feed = frameSource.frames;
  const double dt = 1.0 / def.step.rateHz;
  if (!parser.isSet(input) && !parser.isSet(script)) {
    feed.resize(static_cast<std::size_t>(frameLimit >= 0 ? frameLimit : 100));
    for (std::size_t k = 0; k < feed.size(); ++k) feed[k].time = static_cast<double>(k) * dt;
  }
  if (frameLimit >= 0 && static_cast<std::size_t>(frameLimit) < feed.size())
    feed.resize(static_cast<std::size_t>(frameLimit));

  sim::RecordingWriter writer;
  if (parser.isSet(record)) {
    nlohmann::json meta;
    meta["scene"] = parser.value(scene).toStdString();
    if (parser.isSet(script)) meta["script"] = parser.value(script).toStdString();
    const sim::RecordingStatus s = writer.open(parser.value(record).toStdString(), meta.dump());
    if (!s.ok()) {
      io.err << prefix << parser.value(record) << ": " << recordingErrorText(s.error) << '\n';
      return kExitFailure;
    }
  }

  // the run
  const std::string sceneFile = parser.value(scene).toStdString();
  sim::Scene run(std::move(def), parser.isSet(realtime) ? sim::StepMode::RealTime : sim::StepMode::Deterministic);
  std::array<std::vector<double>, 5> times;
  for (const sim::InputFrame& f : feed) {
    const sim::StepReport r = run.step(f);
    times[0].push_back(r.times.collision);
    times[1].push_back(r.times.tissue);
    times[2].push_back(r.times.suture);
    times[3].push_back(r.times.interactions);
    times[4].push_back(r.times.total);
    if (writer.isOpen() && !writer.append(f).ok()) {
      io.err << prefix << parser.value(record) << ": " << recordingErrorText(sim::RecordingError::CannotWrite) << '\n';
      return kExitFailure;
    }
  }
  if (writer.isOpen() && !writer.finish().ok()) {
    io.err << prefix << parser.value(record) << ": " << recordingErrorText(sim::RecordingError::CannotWrite) << '\n';
    return kExitFailure;
  }

  // the table
  QTextStream& out = io.out;
  const std::uint64_t hash = run.hash();
  out << Cli::tr("scene") << "  " << QString::fromStdString(sceneFile) << '\n'
      << Cli::tr("steps") << "  " << run.steps() << Cli::tr(" of %1 s").arg(dt, 0, 'g', 4) << '\n'
      << Cli::tr("state hash") << "  " << hex(hash) << "\n\n"
      << Cli::tr("events") << '\n';
  for (const sim::SceneEvent& e : run.events()) {
    out << "  " << QString::number(e.time, 'f', 2).rightJustified(7) << " s  " << eventText(e);
    if (e.kind == sim::SceneEventKind::PierceEntry || e.kind == sim::SceneEventKind::PierceExit) {
      const sim::PierceEvent& p = run.pierces()[static_cast<std::size_t>(e.index)];
      out << "  " << Cli::tr("end %1, angle %2°, bite %3 mm, at (%4, %5, %6)")
                         .arg(p.end)
                         .arg(p.angleDeg, 0, 'f', 2)
                         .arg(p.biteMm, 0, 'f', 3)
                         .arg(p.point.x(), 0, 'f', 4)
                         .arg(p.point.y(), 0, 'f', 4)
                         .arg(p.point.z(), 0, 'f', 4);
    }
    out << '\n';
  }
  const char* stageKeys[5] = {"collision", "tissue", "suture", "interactions", "total"};
  const QString stageNames[5] = {Cli::tr("collision"), Cli::tr("tissue"), Cli::tr("suture"),
                                 Cli::tr("interactions"), Cli::tr("total")};
  out << '\n' << Cli::tr("step time (ms)").leftJustified(16) << Cli::tr("median").rightJustified(10)
      << Cli::tr("p99").rightJustified(10) << Cli::tr("max").rightJustified(10) << '\n';
  std::array<Spread, 5> spreads;
  for (int s = 0; s < 5; ++s) {
    spreads[static_cast<std::size_t>(s)] = spread(times[static_cast<std::size_t>(s)]);
    const Spread& v = spreads[static_cast<std::size_t>(s)];
    out << stageNames[s].leftJustified(16) << QString::number(v.median, 'f', 3).rightJustified(10)
        << QString::number(v.p99, 'f', 3).rightJustified(10) << QString::number(v.max, 'f', 3).rightJustified(10)
        << '\n';
  }

  if (parser.isSet(json)) {
    nlohmann::json doc;
    doc["scene"] = sceneFile;
    doc["steps"] = run.steps();
    doc["dt"] = dt;
    doc["hash"] = hex(hash).toStdString();
    nlohmann::json events = nlohmann::json::array();
    for (const sim::SceneEvent& e : run.events()) {
      nlohmann::json j = {{"kind", eventKey(e.kind)}, {"time", e.time}, {"step", e.step},
                          {"hand", e.hand}, {"index", e.index}, {"count", e.count}};
      if (e.kind == sim::SceneEventKind::PierceEntry || e.kind == sim::SceneEventKind::PierceExit) {
        const sim::PierceEvent& p = run.pierces()[static_cast<std::size_t>(e.index)];
        j["pierce"] = {{"point", {p.point.x(), p.point.y(), p.point.z()}},
                       {"face", p.face},
                       {"barycentric", {p.barycentric.x(), p.barycentric.y(), p.barycentric.z()}},
                       {"tangent", {p.tangent.x(), p.tangent.y(), p.tangent.z()}},
                       {"normal", {p.normal.x(), p.normal.y(), p.normal.z()}},
                       {"angle_deg", p.angleDeg},
                       {"vessel", p.vessel},
                       {"end", p.end},
                       {"surface", static_cast<int>(p.surface)},
                       {"wall", p.wall == sim::VesselWall::Front ? "front" : "back"},
                       {"bite_mm", p.biteMm}};
      }
      events.push_back(std::move(j));
    }
    doc["events"] = std::move(events);
    for (int s = 0; s < 5; ++s) {
      const Spread& v = spreads[static_cast<std::size_t>(s)];
      doc["timings_ms"][stageKeys[s]] = {{"median", v.median}, {"p99", v.p99}, {"max", v.max}};
    }
    QString why;
    if (!writeOutputFile(parser.value(json), QByteArray::fromStdString(doc.dump(1) + "\n"), why)) {
      io.err << prefix << Cli::tr("cannot write %1: %2").arg(parser.value(json), why) << '\n';
      return kExitFailure;
    }
  }
  return kExitOk;
}

}  // namespace microsim::cli
