#include "cli/score_report.h"

#include "i18n/end_product_words.h"
#include "microsim/assessment/scoring/end_product.h"
#include "microsim/assessment/scoring/pierce_fields.h"

#include <cmath>
#include <string>
#include <utility>

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

// a 0-based index shown 1-based, as the pierces are numbered; "–" for none
QString endProductIndexText(int index) {
  return index >= 0 ? QString::number(index + 1) : QStringLiteral("–");
}

void printEndProduct(QTextStream& out, const as::AttemptScore& s) {
  out << Cli::tr("end product") << "  "
      << Cli::tr("lapse index %1").arg(static_cast<int>(s.endProduct.size())) << '\n';
  if (s.endProduct.empty()) {
    out << "  " << Cli::tr("none") << '\n';
    return;
  }
  out << "      " << Cli::tr("error").leftJustified(26) << Cli::tr("stitch").rightJustified(7)
      << Cli::tr("pierce").rightJustified(8) << Cli::tr("at (°)").rightJustified(8)
      << Cli::tr("measured").rightJustified(10) << Cli::tr("limit").rightJustified(8) << "  "
      << Cli::tr("unit") << '\n';
  for (std::size_t i = 0; i < s.endProduct.size(); ++i) {
    const as::EndProductError& e = s.endProduct[i];
    out << "  " << QString::number(i + 1).rightJustified(2) << "  "
        << i18n::EndProductWords::kind(e.kind).leftJustified(26)
        << endProductIndexText(e.stitch).rightJustified(7)
        << endProductIndexText(e.passage).rightJustified(8)
        << number(e.angleDeg, 1).rightJustified(8) << number(e.measured, 3).rightJustified(10)
        << number(e.limit, 2).rightJustified(8);
    if (std::isfinite(e.measured)) out << "  " << QLatin1String(as::endProductErrorUnit(e.kind));
    out << '\n';
  }
}

// a stable key for the leak test's status, for the JSON
const char* leakStatusKey(sim::LeakTestStatus status) {
  using S = sim::LeakTestStatus;
  switch (status) {
    case S::Solved:
      return "solved";
    case S::NoSeveredVessel:
      return "no_severed_vessel";
    case S::NoStitches:
      return "no_stitches";
    case S::BadTie:
      return "bad_tie";
    case S::NotConverged:
      return "not_converged";
    case S::SolverFailed:
      return "solver_failed";
  }
  return "";
}

// why a leak test gave no verdict
QString leakNotDoneText(sim::LeakTestStatus status) {
  using S = sim::LeakTestStatus;
  switch (status) {
    case S::Solved:
      return {};
    case S::NoSeveredVessel:
      return Cli::tr("the scene has no severed vessel");
    case S::NoStitches:
      return Cli::tr("no stitch joins the two ends");
    case S::BadTie:
      return Cli::tr("a stitch names a face the tissue does not have");
    case S::NotConverged:
      return Cli::tr("the pressurised wall did not settle");
    case S::SolverFailed:
      return Cli::tr("the pressurised wall could not be solved");
  }
  return {};
}

void printLeakTest(QTextStream& out, const as::AttemptScore& s) {
  if (!s.leak) return;
  const as::LeakFinding& leak = *s.leak;
  out << '\n' << Cli::tr("leak test") << "  ";
  if (leak.status != sim::LeakTestStatus::Solved) {
    out << Cli::tr("not done: %1").arg(leakNotDoneText(leak.status)) << '\n';
    return;
  }
  out << Cli::tr("%1 mmHg: largest gap %2 mm at %3°, limit %4 mm")
             .arg(number(leak.pressureMmHg, 0), number(leak.largestGapMm, 3),
                  number(leak.angleDeg, 1), number(leak.limitMm, 3))
      << "  " << (leak.leaks ? Cli::tr("leaks") : Cli::tr("holds")) << '\n';
}

// the leak test, or null when the attempt had none
nlohmann::json leakJson(const as::AttemptScore& s) {
  if (!s.leak) return nullptr;
  const as::LeakFinding& leak = *s.leak;
  return {{"status", leakStatusKey(leak.status)},
          {"leaks", leak.leaks},
          {"largest_gap_mm", jsonNumber(leak.largestGapMm)},
          {"angle_deg", jsonNumber(leak.angleDeg)},
          {"limit_mm", jsonNumber(leak.limitMm)},
          {"pressure_mmhg", jsonNumber(leak.pressureMmHg)}};
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
  for (const as::PierceMetrics& p : s.pierces) {
    nlohmann::json pierce = {{"vessel", p.vessel},
                             {"end", p.end},
                             {"entry_surface", surfaceKey(p.entrySurface)},
                             {"exit_surface", surfaceKey(p.exitSurface)}};
    for (const as::PierceField& field : as::pierceFields()) {
      const double v = field.value(p);
      pierce[std::string(field.key)] = field.unit == "flag" ? nlohmann::json(v > 0.5) : jsonNumber(v);
    }
    pierces.push_back(std::move(pierce));
  }
  return pierces;
}

// indices are 0-based into "stitches" and "pierces", null for none
nlohmann::json endProductJson(const as::AttemptScore& s) {
  const auto index = [](int i) { return i >= 0 ? nlohmann::json(i) : nlohmann::json(); };
  nlohmann::json errors = nlohmann::json::array();
  for (const as::EndProductError& e : s.endProduct)
    errors.push_back({{"kind", std::string(as::endProductErrorKey(e.kind))},
                      {"stitch", index(e.stitch)},
                      {"pierce", index(e.passage)},
                      {"angle_deg", jsonNumber(e.angleDeg)},
                      {"measured", jsonNumber(e.measured)},
                      {"limit", jsonNumber(e.limit)},
                      {"unit", std::string(as::endProductErrorUnit(e.kind))}});
  return errors;
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
  out << '\n';
  printEndProduct(out, s);
  printLeakTest(out, s);
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
  doc["end_product"] = endProductJson(s);
  doc["leak"] = leakJson(s);
  return doc;
}

}  // namespace microsim::cli
