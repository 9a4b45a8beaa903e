#include "microsim/assessment/storage/people_store.h"

#include "microsim/assessment/storage/password_hash.h"

#include "storage/sql_util.h"

#include <QSqlError>
#include <QSqlQuery>

namespace microsim::assessment {

namespace {

constexpr const char* kPersonColumns =
    "SELECT t.id, t.name, t.role, COALESCE(g.name, '') FROM trainees t "
    "LEFT JOIN trainee_groups g ON g.id = t.group_id ";

Trainee readPerson(const QSqlQuery& q) {
  Trainee t;
  t.id = q.value(0).toLongLong();
  t.name = q.value(1).toString();
  t.role = sql::roleFromText(q.value(2).toString()).value_or(Role::Trainee);
  t.group = q.value(3).toString();
  return t;
}

}  // namespace

QList<Trainee> PeopleStore::trainees() {
  QList<Trainee> out;
  if (!requireOpen()) return out;
  QSqlQuery q(db_.connection());
  if (!q.exec(QString::fromLatin1(kPersonColumns) + QStringLiteral("ORDER BY t.name, t.id"))) {
    fail(HistoryError::QueryFailed, q.lastError().text());
    return out;
  }
  while (q.next()) out << readPerson(q);
  succeed();
  return out;
}

std::optional<Trainee> PeopleStore::person(qint64 id) {
  if (!requireOpen()) return std::nullopt;
  QSqlQuery q(db_.connection());
  q.prepare(QString::fromLatin1(kPersonColumns) + QStringLiteral("WHERE t.id = ?"));
  q.addBindValue(id);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (!q.next()) return fail(HistoryError::NotFound), std::nullopt;
  succeed();
  return readPerson(q);
}

QStringList PeopleStore::groups() {
  QStringList out;
  if (!requireOpen()) return out;
  QSqlQuery q(db_.connection());
  if (!q.exec(QStringLiteral("SELECT name FROM trainee_groups ORDER BY name")))
    return fail(HistoryError::QueryFailed, q.lastError().text()), out;
  while (q.next()) out << q.value(0).toString();
  succeed();
  return out;
}

namespace {

// the person's id, or 0 when the name is free; nullopt on a driver error
std::optional<qint64> idByName(const QSqlDatabase& db, const QString& name) {
  QSqlQuery q(db);
  q.prepare(QStringLiteral("SELECT id FROM trainees WHERE name = ?"));
  q.addBindValue(name);
  if (!q.exec()) return std::nullopt;
  return q.next() ? q.value(0).toLongLong() : 0;
}

// inserts a person (and their group when new) inside the caller's transaction
std::optional<qint64> insertPerson(const QSqlDatabase& db, const QString& name, Role role,
                                   const QString& group, QString* error) {
  QVariant groupId{QMetaType(QMetaType::LongLong)};  // braces: clang reads parentheses as a function declaration
  QSqlQuery q(db);
  if (!group.isEmpty()) {
    q.prepare(QStringLiteral("SELECT id FROM trainee_groups WHERE name = ?"));
    q.addBindValue(group);
    if (!q.exec()) return *error = q.lastError().text(), std::nullopt;
    if (q.next()) {
      groupId = q.value(0).toLongLong();
    } else {
      q.prepare(QStringLiteral("INSERT INTO trainee_groups (name, created_at) VALUES (?, ?) RETURNING id"));
      q.addBindValue(group);
      q.addBindValue(sql::now());
      if (!q.exec() || !q.next()) return *error = q.lastError().text(), std::nullopt;
      groupId = q.value(0).toLongLong();
    }
  }
  q.prepare(QStringLiteral(
      "INSERT INTO trainees (name, role, created_at, group_id) VALUES (?, ?, ?, ?) RETURNING id"));
  q.addBindValue(name);
  q.addBindValue(sql::roleText(role));
  q.addBindValue(sql::now());
  q.addBindValue(groupId);
  if (!q.exec() || !q.next()) return *error = q.lastError().text(), std::nullopt;
  return q.value(0).toLongLong();
}

}  // namespace

std::optional<qint64> PeopleStore::addTrainee(const QString& name, const QString& group) {
  if (!requireOpen()) return std::nullopt;
  if (name.trimmed().isEmpty()) return fail(HistoryError::InvalidInput), std::nullopt;
  QSqlDatabase db = db_.connection();
  const std::optional<qint64> existing = idByName(db, name);
  if (!existing) return fail(HistoryError::QueryFailed, db.lastError().text()), std::nullopt;
  if (*existing != 0) return fail(HistoryError::NameTaken), std::nullopt;

  QString error;
  if (!db.transaction()) return fail(HistoryError::QueryFailed, db.lastError().text()), std::nullopt;
  const std::optional<qint64> id = insertPerson(db, name, Role::Trainee, group, &error);
  if (!id || !db.commit()) {
    db.rollback();
    return fail(HistoryError::QueryFailed, error), std::nullopt;
  }
  succeed();
  return id;
}

std::optional<qint64> PeopleStore::addInstructor(const QString& name, const QString& password) {
  return insertInstructor(name, password, false);
}

std::optional<qint64> PeopleStore::addFirstInstructor(const QString& name, const QString& password) {
  return insertInstructor(name, password, true);
}

namespace {

// the number of instructors; nullopt on a driver error
std::optional<qint64> instructorCount(const QSqlDatabase& db) {
  QSqlQuery q(db);
  if (!q.exec(QStringLiteral("SELECT COUNT(*) FROM trainees WHERE role = 'instructor'")) || !q.next())
    return std::nullopt;
  return q.value(0).toLongLong();
}

}  // namespace

std::optional<qint64> PeopleStore::insertInstructor(const QString& name, const QString& password, bool onlyTheFirst) {
  if (!requireOpen()) return std::nullopt;
  if (name.trimmed().isEmpty() || password.size() < kMinPasswordLength)
    return fail(HistoryError::InvalidInput), std::nullopt;
  QSqlDatabase db = db_.connection();
  const std::optional<qint64> existing = idByName(db, name);
  if (!existing) return fail(HistoryError::QueryFailed, db.lastError().text()), std::nullopt;
  if (*existing != 0) return fail(HistoryError::NameTaken), std::nullopt;

  // the slow hash first, outside the transaction
  const PasswordHash hash = hashPassword(password, db_.passwordIterations());
  QString error;
  if (!db.transaction()) return fail(HistoryError::QueryFailed, db.lastError().text()), std::nullopt;
  if (onlyTheFirst) {
    // checked inside the insert's transaction, so the check and the insert are one change
    const std::optional<qint64> count = instructorCount(db);
    if (!count || *count > 0) {
      db.rollback();
      return fail(count ? HistoryError::Forbidden : HistoryError::QueryFailed, db.lastError().text()), std::nullopt;
    }
  }
  std::optional<qint64> id = insertPerson(db, name, Role::Instructor, {}, &error);
  if (id) {
    QSqlQuery q(db);
    q.prepare(QStringLiteral(
        "INSERT INTO instructor_passwords (trainee_id, algorithm, iterations, salt, hash, set_at) "
        "VALUES (?, ?, ?, ?, ?, ?)"));
    q.addBindValue(*id);
    q.addBindValue(hash.algorithm);
    q.addBindValue(hash.iterations);
    q.addBindValue(hash.salt);
    q.addBindValue(hash.hash);
    q.addBindValue(sql::now());
    if (!q.exec()) {
      error = q.lastError().text();
      id.reset();
    }
  }
  if (!id || !db.commit()) {
    db.rollback();
    return fail(HistoryError::QueryFailed, error), std::nullopt;
  }
  succeed();
  return id;
}

std::optional<qint64> PeopleStore::verifyInstructor(const QString& name, const QString& password) {
  if (!requireOpen()) return std::nullopt;
  QSqlQuery q(db_.connection());
  q.prepare(QStringLiteral(
      "SELECT t.id, p.algorithm, p.iterations, p.salt, p.hash FROM trainees t "
      "JOIN instructor_passwords p ON p.trainee_id = t.id WHERE t.name = ? AND t.role = 'instructor'"));
  q.addBindValue(name);
  if (!q.exec()) return fail(HistoryError::QueryFailed, q.lastError().text()), std::nullopt;
  if (!q.next()) {
    // an unknown name costs as much as a wrong password
    pbkdf2HmacSha256(password.toUtf8(), QByteArray(16, '\0'), db_.passwordIterations(), 32);
    return fail(HistoryError::WrongPassword), std::nullopt;
  }
  PasswordHash stored;
  stored.algorithm = q.value(1).toString();
  stored.iterations = q.value(2).toInt();
  stored.salt = q.value(3).toByteArray();
  stored.hash = q.value(4).toByteArray();
  if (!verifyPassword(password, stored)) return fail(HistoryError::WrongPassword), std::nullopt;
  succeed();
  return q.value(0).toLongLong();
}

}  // namespace microsim::assessment
