#pragma once
// The rows the history hands out: people, attempts, stored scores and annotations.
// Plain values; the stores (history_database.h) read and write them. Times are UTC.

#include "microsim/assessment/scoring/end_product.h"

#include <QByteArray>
#include <QDateTime>
#include <QList>
#include <QString>
#include <QtGlobal>

#include <optional>

namespace microsim::assessment {

enum class Role { Trainee, Instructor };
enum class AttemptMode { Learn, Test };
enum class AttemptStatus {
  InProgress,   ///< begun, not yet scored
  Finished,     ///< scored; its score, metrics and recording can no longer change
  Interrupted,  ///< the session that began it ended without finishing it (crash, kill)
  Abandoned,    ///< the trainee gave it up (confirmed); never scored
};

/// Who is asking. A trainee sees only their own attempts; an instructor sees every
/// attempt and may annotate. The storage checks `role` against the person's stored role
/// on every call, so a trainee's id with Role::Instructor is refused.
struct Viewer {
  qint64 userId = 0;
  Role role = Role::Trainee;
};

struct Trainee {
  qint64 id = 0;
  QString name;
  Role role = Role::Trainee;
  QString group;  ///< empty when the person is in no group
};

struct AttemptSummary {
  qint64 id = 0;
  qint64 traineeId = 0;
  QString lesson;
  AttemptMode mode = AttemptMode::Learn;
  AttemptStatus status = AttemptStatus::InProgress;
  QDateTime started;
  QDateTime finished;          ///< invalid while in progress
  std::optional<double> score; ///< 0..100, only when finished
  bool passed = false;
  QString rubricId;
  int rubricVersion = 0;
};

/// One metric of a stored score (mirrors MetricScore; units as the rubric gives them).
struct StoredMetric {
  QString key;
  double value = 0;
  QString unit;
  double target = 0;
  double tolerance = 0;
  double weight = 0;
  double points = 0;    ///< 0..1
  QString feedback;     ///< a key such as "entry_angle.too_oblique"
};

/// One value measured on one pierce (e.g. pierce 2, "entry_angle_deg", 84.0).
struct StoredPierceValue {
  int pierce = 0;  ///< 0-based, in the order the pierces happened
  QString key;
  double value = 0;
};

/// The finished anastomosis's errors (scoring/end_product.h) as stored with a score.
struct StoredEndProduct {
  /// false when the attempt was never judged so: not scored, or scored before the history
  /// kept end-product errors (which is not the same as judged clean)
  bool judged = false;
  QList<EndProductError> errors;  ///< in the scorer's order
};

struct Annotation {
  qint64 id = 0;
  qint64 attemptId = 0;
  qint64 authorId = 0;
  QString authorName;
  QString note;
  QDateTime created;
};

/// Everything stored about one attempt.
struct AttemptDetail {
  AttemptSummary summary;
  QList<StoredMetric> metrics;
  QList<StoredPierceValue> pierces;
  QStringList neverEvents;
  StoredEndProduct endProduct;
  QList<Annotation> annotations;
  QByteArray recording;  ///< the .msrec bytes; empty when none was stored
};

}  // namespace microsim::assessment
