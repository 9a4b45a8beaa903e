-- Migration 4: an attempt the trainee gave up on is stored as 'abandoned', told apart from
-- 'interrupted' (the session that began it ended without finishing it: a crash, a kill).
--
-- SQLite cannot change a CHECK constraint in place, so the attempts table is rebuilt with
-- its rows and ids (SQLite's procedure for other schema changes: the runner keeps foreign
-- keys off during SQLite migrations and checks them before committing, so dropping the old
-- table cascades nothing). The triggers that name the table in their bodies are dropped
-- first and made again after, as are its own trigger and indexes. PostgreSQL swaps the
-- constraint.

@SQLITE@ DROP TRIGGER scores_only_in_progress;

@SQLITE@ DROP TRIGGER score_metrics_only_in_progress;

@SQLITE@ DROP TRIGGER score_pierces_only_in_progress;

@SQLITE@ DROP TRIGGER recordings_only_in_progress;

@SQLITE@ CREATE TABLE attempts_rebuilt (
  id              INTEGER PRIMARY KEY,
  trainee_id      INTEGER NOT NULL REFERENCES trainees(id) ON DELETE CASCADE,
  lesson          TEXT NOT NULL,
  mode            TEXT NOT NULL CHECK (mode IN ('learn', 'test')),
  status          TEXT NOT NULL DEFAULT 'in_progress'
                  CHECK (status IN ('in_progress', 'finished', 'interrupted', 'abandoned')),
  started_at      TEXT NOT NULL,
  finished_at     TEXT,
  session         TEXT
);

@SQLITE@ INSERT INTO attempts_rebuilt (id, trainee_id, lesson, mode, status, started_at, finished_at, session)
  SELECT id, trainee_id, lesson, mode, status, started_at, finished_at, session FROM attempts;

@SQLITE@ DROP TABLE attempts;

@SQLITE@ ALTER TABLE attempts_rebuilt RENAME TO attempts;

@SQLITE@ CREATE INDEX attempts_by_trainee ON attempts(trainee_id, started_at);

@SQLITE@ CREATE INDEX attempts_by_status ON attempts(status);

@SQLITE@ CREATE TRIGGER attempts_finished_stay BEFORE UPDATE ON attempts WHEN OLD.status = 'finished' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER scores_only_in_progress BEFORE INSERT ON scores WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_metrics_only_in_progress BEFORE INSERT ON score_metrics WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_pierces_only_in_progress BEFORE INSERT ON score_pierces WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER recordings_only_in_progress BEFORE INSERT ON recordings WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@POSTGRESQL@ ALTER TABLE attempts DROP CONSTRAINT attempts_status_check;

@POSTGRESQL@ ALTER TABLE attempts ADD CONSTRAINT attempts_status_check
  CHECK (status IN ('in_progress', 'finished', 'interrupted', 'abandoned'));
