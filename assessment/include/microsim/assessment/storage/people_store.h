#pragma once
// The people of a history (tables trainees, trainee_groups, instructor_passwords):
// trainees, instructors with a salted PBKDF2-HMAC-SHA256 hash of their password
// (password_hash.h), and the groups trainees belong to.

#include "microsim/assessment/storage/history_store.h"

#include <QStringList>

#include <optional>

namespace microsim::assessment {

class PeopleStore : public HistoryStore {
 public:
  static constexpr int kMinPasswordLength = 8;

  explicit PeopleStore(HistoryDatabase& database) : HistoryStore(database) {}

  /// Everyone, trainees and instructors, by name.
  QList<Trainee> trainees();
  std::optional<Trainee> person(qint64 id);
  /// A trainee; `group` is created when new. nullopt: NameTaken, InvalidInput, ...
  std::optional<qint64> addTrainee(const QString& name, const QString& group = {});
  /// An instructor with a salted hash of `password` (HistoryDatabase::passwordIterations).
  std::optional<qint64> addInstructor(const QString& name, const QString& password);
  /// The first instructor of a history that has none (the app's first-run path, open to
  /// whoever starts it): as addInstructor, but Forbidden once any instructor exists, checked
  /// in the same transaction as the insert.
  std::optional<qint64> addFirstInstructor(const QString& name, const QString& password);
  /// The instructor's id when the password matches (constant-time compare).
  std::optional<qint64> verifyInstructor(const QString& name, const QString& password);
  QStringList groups();

 private:
  std::optional<qint64> insertInstructor(const QString& name, const QString& password, bool onlyTheFirst);
};

}  // namespace microsim::assessment
