#pragma once
// Setup profiles: one named calibration of a station (which tracked device each hand
// holds, the forceps' closure channel and range, the tool-tip offsets, the tracker → scene
// registration, motion scaling, latency), with its errors, date and who calibrated it.
// A technician calibrates once; trainees choose the profile at start.
//
// The profile's whole content is its JSON document (exportProfileJson); the table
// setup_profiles (migration 0003) keeps that document plus the columns a list shows.
// Import validates every field and names the first one at fault, as a path such as
// "hands[1].tip_offset_mm" (data for the app's message, not a sentence).
//
// JSON (version 1):
//   {"format": "microsim-setup-profile", "version": 1, "name": "Bench 2",
//    "calibrated_at": "2026-11-22T17:00:00Z", "calibrated_by": "J. Tech",
//    "hands": [{"device": "Stylus", "instrument": "forceps", "closure_channel": "Grip",
//               "closure_open": 0.0, "closure_closed": 1.0, "tip_offset_mm": [x, y, z],
//               "pivot_rms_mm": 0.12 | null}, {... right hand ...}],
//    "tracker_to_scene": [16 numbers, row-major], "fre_mm": 0.3 | null, "tre_mm": 0.5 | null,
//    "motion_scaling": {"hand_per_scene": 3.0, "anchor_mm": [x, y, z]}, "latency_s": 0.02 | null}

#include "microsim/assessment/storage/history_database.h"
#include "microsim/sim/scene/input_frame.h"

#include <Eigen/Core>

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>

#include <array>
#include <optional>
#include <variant>

namespace microsim::assessment {

struct ProfileHand {
  QString device;                 ///< tracked device (OpenIGTLink name); empty: hand unused
  sim::Instrument instrument = sim::Instrument::Forceps;
  QString closureChannel;         ///< channel of the forceps' grip; empty: closure stays 0
  double closureOpen = 0.0;       ///< channel value with open jaws (channel unit)
  double closureClosed = 1.0;     ///< channel value with closed jaws (channel unit)
  Eigen::Vector3d tipOffset = Eigen::Vector3d::Zero();  ///< tip in the tool frame, mm
  std::optional<double> pivotRmsMm;                      ///< mm, RMS of the pivot calibration

  bool operator==(const ProfileHand&) const = default;
};

struct SetupProfile {
  qint64 id = 0;  ///< database id; 0 until saved
  QString name;
  std::array<ProfileHand, sim::kHandCount> hands{};
  Eigen::Matrix4d trackerToScene = Eigen::Matrix4d::Identity();  ///< homogeneous similarity, mm
  std::optional<double> freMm;                ///< mm, fiducial registration error (RMS)
  std::optional<double> treMm;                ///< mm, target registration error (RMS)
  double handPerScene = 1.0;                  ///< mm of hand motion per mm of scene motion (> 0)
  Eigen::Vector3d scalingAnchor = Eigen::Vector3d::Zero();  ///< scene point fixed by scaling, mm
  std::optional<double> latencyS;             ///< s, tracker latency estimate
  QDateTime calibratedAt;                     ///< UTC
  QString calibratedBy;

  /// Equal content (the id is not compared).
  bool sameContent(const SetupProfile& o) const;
};

enum class ProfileJsonProblem {
  NotJson,      ///< not a JSON object
  WrongFormat,  ///< "format" is not "microsim-setup-profile" or the version is unknown
  Missing,      ///< a required field is absent
  WrongType,    ///< a field has the wrong JSON type or length
  OutOfRange,   ///< a value is not allowed (non-finite, ≤ 0 scaling, not a similarity, ...)
};

struct ProfileJsonError {
  ProfileJsonProblem problem = ProfileJsonProblem::NotJson;
  QString field;  ///< path of the field at fault ("hands[0].device"); empty for NotJson
};

/// Stable key of an instrument in profiles ("forceps", "needle_holder", "scalpel", "none").
QString instrumentKey(sim::Instrument instrument);

QByteArray exportProfileJson(const SetupProfile& profile);
/// Parses and validates; the id of the result is 0.
std::variant<SetupProfile, ProfileJsonError> importProfileJson(const QByteArray& json);

struct SetupProfileSummary {
  qint64 id = 0;
  QString name;
  QDateTime calibratedAt;
  QString calibratedBy;
  std::optional<double> freMm;
  std::optional<double> treMm;
};

/// The profiles of a HistoryDatabase (which must stay open while this is used).
class SetupProfileStore {
 public:
  explicit SetupProfileStore(HistoryDatabase& database) : db_(database) {}

  /// Inserts, or replaces the profile of the same name; returns its id.
  std::optional<qint64> save(const SetupProfile& profile);
  std::optional<SetupProfile> load(qint64 id);
  std::optional<SetupProfile> loadByName(const QString& name);
  /// Every profile, newest calibration first.
  QList<SetupProfileSummary> list();
  bool remove(qint64 id);
  /// The driver's text of the last failure (data, not for display as is).
  QString lastError() const { return lastError_; }

 private:
  std::optional<SetupProfile> loadWhere(const QString& column, const QVariant& value);

  HistoryDatabase& db_;
  QString lastError_;
};

}  // namespace microsim::assessment
