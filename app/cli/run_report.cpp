#include "cli/run_report.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

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
    case K::ThreadCut:
      return "thread-cut";
    case K::ThreadTooShort:
      return "thread-too-short";
    case K::ThrowFormed:
      return "throw-formed";
    case K::KnotTightened:
      return "knot-tightened";
    case K::KnotSlipped:
      return "knot-slipped";
  }
  return "";
}

QString knotTypeText(sim::suture::KnotType type) {
  using T = sim::suture::KnotType;
  switch (type) {
    case T::None:
      return Cli::tr("no knot");
    case T::SingleThrow:
      return Cli::tr("a single throw");
    case T::Square:
      return Cli::tr("a square knot");
    case T::Granny:
      return Cli::tr("a granny knot");
    case T::Surgeons:
      return Cli::tr("a surgeon's knot");
    case T::SlipKnot:
      return Cli::tr("a slip knot");
    case T::Unknown:
      return Cli::tr("an unknown knot");
  }
  return {};
}

QString handednessText(sim::suture::Handedness h) {
  return h == sim::suture::Handedness::Right ? Cli::tr("right-handed") : Cli::tr("left-handed");
}

// the knot's fields for JSON: names for programs, not translated
const char* knotTypeKey(sim::suture::KnotType type) {
  using T = sim::suture::KnotType;
  switch (type) {
    case T::None:
      return "none";
    case T::SingleThrow:
      return "single-throw";
    case T::Square:
      return "square";
    case T::Granny:
      return "granny";
    case T::Surgeons:
      return "surgeons";
    case T::SlipKnot:
      return "slip-knot";
    case T::Unknown:
      return "unknown";
  }
  return "";
}

nlohmann::json knotJson(const sim::SceneEvent& e) {
  nlohmann::json j = {
      {"type", knotTypeKey(e.knot.type)}, {"throws", e.count}, {"tension_uN", e.value}};
  if (e.kind == sim::SceneEventKind::ThrowFormed) {
    j["throw"] = e.index;
    j["handedness"] = e.knot.handedness == sim::suture::Handedness::Right ? "right" : "left";
    j["wraps"] = e.knot.wraps;
  }
  if (e.kind == sim::SceneEventKind::KnotSlipped) {
    j["cause"] = e.knot.cause == sim::suture::KnotSlipCause::Sliding ? "sliding" : "structure-lost";
    j["slide_mm"] = e.knot.slide;
  }
  return j;
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
    case K::ThreadCut:
      return e.value >= 0.0 ? Cli::tr("scissors cut the thread, leaving a %1 mm end").arg(e.value, 0, 'f', 2)
                            : Cli::tr("scissors cut the thread");
    case K::ThreadTooShort:
      return Cli::tr("the needle keeps %1 mm of thread, too short to tie").arg(e.value, 0, 'f', 2);
    case K::ThrowFormed:
      return Cli::tr("throw %1 formed: %2, %n wrap(s); the knot reads %3", nullptr, e.knot.wraps)
          .arg(e.index + 1)
          .arg(handednessText(e.knot.handedness), knotTypeText(e.knot.type));
    case K::KnotTightened:
      return Cli::tr("%1 pulled tight: %n throw(s), tension %2 µN", nullptr, e.count)
          .arg(knotTypeText(e.knot.type))
          .arg(e.value, 0, 'f', 1);
    case K::KnotSlipped:
      return e.knot.cause == sim::suture::KnotSlipCause::Sliding
                 ? Cli::tr("the knot slips: it ran %1 mm along the thread under %2 µN")
                       .arg(e.knot.slide, 0, 'f', 2)
                       .arg(e.value, 0, 'f', 1)
                 : Cli::tr("the knot slips: %n throw(s) left, it reads %1", nullptr, e.count)
                       .arg(knotTypeText(e.knot.type));
  }
  return {};
}

bool isKnot(const sim::SceneEvent& e) {
  using K = sim::SceneEventKind;
  return e.kind == K::ThrowFormed || e.kind == K::KnotTightened || e.kind == K::KnotSlipped;
}

bool isPierce(const sim::SceneEvent& e) {
  return e.kind == sim::SceneEventKind::PierceEntry || e.kind == sim::SceneEventKind::PierceExit;
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
    const std::size_t i =
        static_cast<std::size_t>(std::ceil(q * static_cast<double>(seconds.size()))) - 1;
    return 1e3 * seconds[std::min(i, seconds.size() - 1)];
  };
  s.median = at(0.5);
  s.p99 = at(0.99);
  s.max = 1e3 * seconds.back();
  return s;
}

constexpr std::array<const char*, StepTimeLog::kStages> kStageKeys = {
    "collision", "tissue", "suture", "interactions", "total"};

QString hex(std::uint64_t h) {
  return QStringLiteral("%1").arg(h, 16, 16, QLatin1Char('0'));
}

double stepSeconds(const sim::Scene& scene) {
  return 1.0 / scene.def().step.rateHz;
}

void printEvents(QTextStream& out, const sim::Scene& scene) {
  for (const sim::SceneEvent& e : scene.events()) {
    out << "  " << QString::number(e.time, 'f', 2).rightJustified(7) << " s  " << eventText(e);
    if (isPierce(e)) {
      const sim::PierceEvent& p = scene.pierces()[static_cast<std::size_t>(e.index)];
      out << "  "
          << Cli::tr("end %1, angle %2°, bite %3 mm, at (%4, %5, %6)")
                 .arg(p.end)
                 .arg(p.angleDeg, 0, 'f', 2)
                 .arg(p.biteMm, 0, 'f', 3)
                 .arg(p.point.x(), 0, 'f', 4)
                 .arg(p.point.y(), 0, 'f', 4)
                 .arg(p.point.z(), 0, 'f', 4);
    }
    out << '\n';
  }
}

void printStepTimes(QTextStream& out, const StepTimeLog& times) {
  const std::array<QString, StepTimeLog::kStages> names = {
      Cli::tr("collision"), Cli::tr("tissue"), Cli::tr("suture"), Cli::tr("interactions"),
      Cli::tr("total")};
  out << Cli::tr("step time (ms)").leftJustified(16) << Cli::tr("median").rightJustified(10)
      << Cli::tr("p99").rightJustified(10) << Cli::tr("max").rightJustified(10) << '\n';
  for (int s = 0; s < StepTimeLog::kStages; ++s) {
    const Spread v = spread(times.stage(s));
    out << names[static_cast<std::size_t>(s)].leftJustified(16)
        << QString::number(v.median, 'f', 3).rightJustified(10)
        << QString::number(v.p99, 'f', 3).rightJustified(10)
        << QString::number(v.max, 'f', 3).rightJustified(10) << '\n';
  }
}

nlohmann::json pierceJson(const sim::PierceEvent& p) {
  return {{"point", {p.point.x(), p.point.y(), p.point.z()}},
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

}  // namespace

void StepTimeLog::add(const sim::StageTimes& times) {
  const std::array<double, kStages> byStage = {times.collision, times.tissue, times.suture,
                                               times.interactions, times.total};
  for (std::size_t s = 0; s < byStage.size(); ++s) seconds_[s].push_back(byStage[s]);
}

void printRunReport(QTextStream& out, const sim::Scene& scene, const QString& sceneFile,
                    const StepTimeLog& times) {
  out << Cli::tr("scene") << "  " << sceneFile << '\n'
      << Cli::tr("steps") << "  " << scene.steps()
      << Cli::tr(" of %1 s").arg(stepSeconds(scene), 0, 'g', 4) << '\n'
      << Cli::tr("state hash") << "  " << hex(scene.hash()) << "\n\n"
      << Cli::tr("events") << '\n';
  printEvents(out, scene);
  out << '\n';
  printStepTimes(out, times);
}

std::string runReportJson(const sim::Scene& scene, const QString& sceneFile,
                          const StepTimeLog& times) {
  nlohmann::json doc;
  doc["scene"] = sceneFile.toStdString();
  doc["steps"] = scene.steps();
  doc["dt"] = stepSeconds(scene);
  doc["hash"] = hex(scene.hash()).toStdString();
  nlohmann::json events = nlohmann::json::array();
  for (const sim::SceneEvent& e : scene.events()) {
    nlohmann::json j = {{"kind", eventKey(e.kind)}, {"time", e.time},   {"step", e.step},
                        {"hand", e.hand},           {"index", e.index}, {"count", e.count}};
    if (e.value != 0.0) j["value"] = e.value;
    if (isPierce(e)) j["pierce"] = pierceJson(scene.pierces()[static_cast<std::size_t>(e.index)]);
    if (isKnot(e)) j["knot"] = knotJson(e);
    events.push_back(std::move(j));
  }
  doc["events"] = std::move(events);
  for (int s = 0; s < StepTimeLog::kStages; ++s) {
    const Spread v = spread(times.stage(s));
    doc["timings_ms"][kStageKeys[static_cast<std::size_t>(s)]] = {
        {"median", v.median}, {"p99", v.p99}, {"max", v.max}};
  }
  return doc.dump(1) + "\n";
}

}  // namespace microsim::cli
