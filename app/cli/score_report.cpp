#include "cli/score_report.h"

#include <cmath>

namespace microsim::cli {

namespace {

namespace as = microsim::assessment;

const char* surfaceKey(sim::VesselSurface s) {
  using S = sim::VesselSurface;
  switch (s) {
    case S::Outer:
      return "outer";
    case S::Inner:
      return "inner";
    case S::CutEnd:
      return "cut-end";
    case S::ClampedEnd:
      return "clamped-end";
    case S::NotAVessel:
      return "none";
  }
  return "";
}

QString number(double v, int decimals) {
  return std::isfinite(v) ? QString::number(v, 'f', decimals) : QStringLiteral("–");
}

// JSON has no NaN: a missing value is null
nlohmann::json jsonNumber(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
}

void printMetrics(QTextStream& out, const as::AttemptScore& s) {
  out << Cli::tr("metric").leftJustified(22) << Cli::tr("value").rightJustified(11) << "  "
      << Cli::tr("unit").leftJustified(6) << Cli::tr("target").rightJustified(9)
      << Cli::tr("weight").rightJustified(8) << Cli::tr("points").rightJustified(8) << "  "
      << Cli::tr("feedback") << '\n';
  for (const as::MetricScore& m : s.metrics)
    out << QString::fromStdString(m.key).leftJustified(22) << number(m.value, 3).rightJustified(11)
        << "  " << QString::fromStdString(m.unit).leftJustified(6)
        << number(m.target, 2).rightJustified(9) << number(m.weight, 1).rightJustified(8)
        << number(m.points, 2).rightJustified(8) << "  " << QString::fromStdString(m.feedback)
        << '\n';
}

void printPierces(QTextStream& out, const as::AttemptScore& s) {
  out << Cli::tr("pierces") << '\n';
  if (s.pierces.empty()) out << "  " << Cli::tr("none") << '\n';
  for (std::size_t i = 0; i < s.pierces.size(); ++i) {
    const as::PierceMetrics& p = s.pierces[i];
    out << "  " << QString::number(i + 1).rightJustified(2) << "  "
        << Cli::tr("%1 s, end %2, %3 → %4, entry %5°, exit %6°, bite %7 mm, at %8°")
               .arg(number(p.time, 2))
               .arg(p.end)
               .arg(QLatin1String(surfaceKey(p.entrySurface)),
                    QLatin1String(surfaceKey(p.exitSurface)))
               .arg(number(p.entryAngleDeg, 1), number(p.exitAngleDeg, 1), number(p.biteMm, 3),
                    number(p.circumferenceDeg, 1));
    if (p.fullThickness) out << ", " << Cli::tr("full thickness");
    if (p.backWall) out << ", " << Cli::tr("back wall");
    out << '\n';
  }
}

nlohmann::json metricsJson(const as::AttemptScore& s) {
  nlohmann::json metrics = nlohmann::json::array();
  for (const as::MetricScore& m : s.metrics)
    metrics.push_back({{"key", m.key},
                       {"value", jsonNumber(m.value)},
                       {"unit", m.unit},
                       {"target", m.target},
                       {"tolerance", m.tolerance},
                       {"weight", m.weight},
                       {"points", m.points},
                       {"feedback", m.feedback}});
  return metrics;
}

nlohmann::json piercesJson(const as::AttemptScore& s) {
  nlohmann::json pierces = nlohmann::json::array();
  for (const as::PierceMetrics& p : s.pierces)
    pierces.push_back({{"time", p.time},
                       {"vessel", p.vessel},
                       {"end", p.end},
                       {"entry_surface", surfaceKey(p.entrySurface)},
                       {"exit_surface", surfaceKey(p.exitSurface)},
                       {"entry_angle_deg", jsonNumber(p.entryAngleDeg)},
                       {"exit_angle_deg", jsonNumber(p.exitAngleDeg)},
                       {"bite_mm", jsonNumber(p.biteMm)},
                       {"bite_walls", jsonNumber(p.biteWalls)},
                       {"circumference_deg", jsonNumber(p.circumferenceDeg)},
                       {"full_thickness", p.fullThickness},
                       {"back_wall", p.backWall}});
  return pierces;
}

nlohmann::json stitchesJson(const as::AttemptScore& s) {
  nlohmann::json stitches = nlohmann::json::array();
  for (const as::StitchMetrics& st : s.stitches)
    stitches.push_back({{"time", st.time},
                        {"bite_a_mm", st.biteAMm},
                        {"bite_b_mm", st.biteBMm},
                        {"symmetry_mm", st.symmetryMm},
                        {"position_deg", jsonNumber(st.positionDeg)},
                        {"spacing_deg", jsonNumber(st.spacingDeg)},
                        {"full_thickness", st.fullThickness}});
  return stitches;
}

}  // namespace

void printScoreReport(QTextStream& out, const as::AttemptScore& s, const as::Rubric& rubric,
                      const ScoredFiles& files) {
  out << Cli::tr("rubric") << "  " << QString::fromStdString(rubric.id) << ' '
      << Cli::tr("version %1, pass mark %2").arg(rubric.version).arg(rubric.passMark) << '\n'
      << Cli::tr("scene") << "  " << files.scene << '\n'
      << Cli::tr("recording") << "  " << files.recording << "  "
      << Cli::tr("%n frame(s)", nullptr, files.frames);
  if (s.truncated) out << "  " << Cli::tr("(unfinished: scored as far as it goes)");
  out << "\n\n"
      << Cli::tr("score") << "  " << QString::number(s.score, 'f', 1) << "  "
      << (s.passed ? Cli::tr("passed") : Cli::tr("not passed")) << '\n';
  for (const std::string& n : s.neverEvents)
    out << "  " << Cli::tr("never-event") << "  " << QString::fromStdString(n) << '\n';
  out << '\n';
  printMetrics(out, s);
  out << '\n';
  printPierces(out, s);
}

nlohmann::json scoreReportJson(const as::AttemptScore& s, const as::Rubric& rubric,
                               const ScoredFiles& files) {
  nlohmann::json doc;
  doc["score"] = s.score;
  doc["passed"] = s.passed;
  doc["rubric"] = {{"id", rubric.id}, {"version", rubric.version}, {"pass_mark", rubric.passMark}};
  doc["scene"] = files.scene.toStdString();
  doc["recording"] = files.recording.toStdString();
  doc["frames"] = files.frames;
  doc["truncated"] = s.truncated;
  doc["never_events"] = s.neverEvents;
  doc["metrics"] = metricsJson(s);
  doc["pierces"] = piercesJson(s);
  doc["stitches"] = stitchesJson(s);
  return doc;
}

}  // namespace microsim::cli
