-- Migration 2: groups, instructors' password hashes, scores with their rubric, per-metric
-- and per-pierce rows, instructors' annotations, recordings; the session that began an
-- attempt (to tell a crashed program's attempts from a live one's); and triggers that
-- refuse to change a stored score.
--
-- Migration 1's score, rubric_version and recording columns and its attempt_metrics table
-- were never written by any release; the scores table and its rows replace them.

CREATE TABLE trainee_groups (
  id          @ID@,
  name        TEXT NOT NULL UNIQUE,
  created_at  TEXT NOT NULL
);

ALTER TABLE trainees ADD COLUMN group_id INTEGER REFERENCES trainee_groups(id) ON DELETE SET NULL;

CREATE TABLE instructor_passwords (
  trainee_id  INTEGER PRIMARY KEY REFERENCES trainees(id) ON DELETE CASCADE,
  algorithm   TEXT NOT NULL CHECK (algorithm IN ('pbkdf2-sha256')),
  iterations  INTEGER NOT NULL CHECK (iterations > 0),
  salt        @BLOB@ NOT NULL,
  hash        @BLOB@ NOT NULL,
  set_at      TEXT NOT NULL
);

ALTER TABLE attempts ADD COLUMN session TEXT;

ALTER TABLE attempts DROP COLUMN score;

ALTER TABLE attempts DROP COLUMN rubric_version;

ALTER TABLE attempts DROP COLUMN recording;

DROP TABLE attempt_metrics;

CREATE INDEX attempts_by_status ON attempts(status);

-- one row per finished attempt; score 0..100
CREATE TABLE scores (
  attempt_id      INTEGER PRIMARY KEY REFERENCES attempts(id) ON DELETE CASCADE,
  score           @REAL@ NOT NULL CHECK (score >= 0 AND score <= 100),
  passed          INTEGER NOT NULL CHECK (passed IN (0, 1)),
  rubric_id       TEXT NOT NULL,
  rubric_version  INTEGER NOT NULL,
  never_events    TEXT NOT NULL DEFAULT '',
  truncated       INTEGER NOT NULL DEFAULT 0 CHECK (truncated IN (0, 1))
);

-- value, target and tolerance in `unit`; points 0..1; NULL value: the attempt lacked it
CREATE TABLE score_metrics (
  attempt_id  INTEGER NOT NULL REFERENCES scores(attempt_id) ON DELETE CASCADE,
  position    INTEGER NOT NULL,
  metric      TEXT NOT NULL,
  value       @REAL@,
  unit        TEXT NOT NULL,
  target      @REAL@ NOT NULL,
  tolerance   @REAL@ NOT NULL,
  weight      @REAL@ NOT NULL,
  points      @REAL@ NOT NULL,
  feedback    TEXT NOT NULL,
  PRIMARY KEY (attempt_id, metric)
);

-- one row per measured value of a pierce (pierce 0-based in entry order); NULL = NaN
CREATE TABLE score_pierces (
  attempt_id  INTEGER NOT NULL REFERENCES scores(attempt_id) ON DELETE CASCADE,
  pierce      INTEGER NOT NULL,
  metric      TEXT NOT NULL,
  value       @REAL@,
  PRIMARY KEY (attempt_id, pierce, metric)
);

CREATE TABLE recordings (
  attempt_id  INTEGER PRIMARY KEY REFERENCES attempts(id) ON DELETE CASCADE,
  data        @BLOB@ NOT NULL
);

CREATE TABLE annotations (
  id          @ID@,
  attempt_id  INTEGER NOT NULL REFERENCES attempts(id) ON DELETE CASCADE,
  author_id   INTEGER NOT NULL REFERENCES trainees(id),
  note        TEXT NOT NULL,
  created_at  TEXT NOT NULL
);

CREATE INDEX annotations_by_attempt ON annotations(attempt_id);

-- a stored score never changes: no UPDATE of its rows, no new rows once finished, and a
-- finished attempt stays finished
@SQLITE@ CREATE TRIGGER scores_no_update BEFORE UPDATE ON scores BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_metrics_no_update BEFORE UPDATE ON score_metrics BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_pierces_no_update BEFORE UPDATE ON score_pierces BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER recordings_no_update BEFORE UPDATE ON recordings BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER attempts_finished_stay BEFORE UPDATE ON attempts WHEN OLD.status = 'finished' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER scores_only_in_progress BEFORE INSERT ON scores WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_metrics_only_in_progress BEFORE INSERT ON score_metrics WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_pierces_only_in_progress BEFORE INSERT ON score_pierces WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER recordings_only_in_progress BEFORE INSERT ON recordings WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@POSTGRESQL@ CREATE FUNCTION microsim_refuse_score_change() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN RAISE EXCEPTION 'stored scores cannot change'; END $$;

@POSTGRESQL@ CREATE FUNCTION microsim_refuse_unless_in_progress() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN IF (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' THEN RAISE EXCEPTION 'stored scores cannot change'; END IF; RETURN NEW; END $$;

@POSTGRESQL@ CREATE TRIGGER scores_no_update BEFORE UPDATE ON scores FOR EACH ROW EXECUTE FUNCTION microsim_refuse_score_change();

@POSTGRESQL@ CREATE TRIGGER score_metrics_no_update BEFORE UPDATE ON score_metrics FOR EACH ROW EXECUTE FUNCTION microsim_refuse_score_change();

@POSTGRESQL@ CREATE TRIGGER score_pierces_no_update BEFORE UPDATE ON score_pierces FOR EACH ROW EXECUTE FUNCTION microsim_refuse_score_change();

@POSTGRESQL@ CREATE TRIGGER recordings_no_update BEFORE UPDATE ON recordings FOR EACH ROW EXECUTE FUNCTION microsim_refuse_score_change();

@POSTGRESQL@ CREATE TRIGGER attempts_finished_stay BEFORE UPDATE ON attempts FOR EACH ROW WHEN (OLD.status = 'finished') EXECUTE FUNCTION microsim_refuse_score_change();

@POSTGRESQL@ CREATE TRIGGER scores_only_in_progress BEFORE INSERT ON scores FOR EACH ROW EXECUTE FUNCTION microsim_refuse_unless_in_progress();

@POSTGRESQL@ CREATE TRIGGER score_metrics_only_in_progress BEFORE INSERT ON score_metrics FOR EACH ROW EXECUTE FUNCTION microsim_refuse_unless_in_progress();

@POSTGRESQL@ CREATE TRIGGER score_pierces_only_in_progress BEFORE INSERT ON score_pierces FOR EACH ROW EXECUTE FUNCTION microsim_refuse_unless_in_progress();

@POSTGRESQL@ CREATE TRIGGER recordings_only_in_progress BEFORE INSERT ON recordings FOR EACH ROW EXECUTE FUNCTION microsim_refuse_unless_in_progress();
