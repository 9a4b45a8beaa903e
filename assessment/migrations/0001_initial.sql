-- Migration 1: trainees, attempts and their metrics.
-- Statements end with a semicolon at the end of a line; the runner applies every
-- statement of a migration, and the migration's row in schema_migrations, in one
-- transaction, so a failed migration leaves the database as it was. @ID@, @REAL@ and
-- @BLOB@ become each driver's types (migrations.h); on SQLite this is the schema that
-- session-1 databases were created with, so they need no change.

CREATE TABLE trainees (
  id          @ID@,
  name        TEXT NOT NULL UNIQUE,
  role        TEXT NOT NULL DEFAULT 'trainee' CHECK (role IN ('trainee', 'instructor')),
  created_at  TEXT NOT NULL
);

CREATE TABLE attempts (
  id              @ID@,
  trainee_id      INTEGER NOT NULL REFERENCES trainees(id) ON DELETE CASCADE,
  lesson          TEXT NOT NULL,
  mode            TEXT NOT NULL CHECK (mode IN ('learn', 'test')),
  status          TEXT NOT NULL DEFAULT 'in_progress'
                  CHECK (status IN ('in_progress', 'finished', 'interrupted')),
  started_at      TEXT NOT NULL,
  finished_at     TEXT,
  score           @REAL@,
  rubric_version  TEXT,
  recording       @BLOB@
);

CREATE INDEX attempts_by_trainee ON attempts(trainee_id, started_at);

CREATE TABLE attempt_metrics (
  attempt_id  INTEGER NOT NULL REFERENCES attempts(id) ON DELETE CASCADE,
  metric      TEXT NOT NULL,
  value       @REAL@ NOT NULL,
  PRIMARY KEY (attempt_id, metric)
);
