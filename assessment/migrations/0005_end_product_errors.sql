-- Migration 5: the finished anastomosis's errors (scoring/end_product.h, issue 19 item 5),
-- stored with the score they were judged with, one row each in the scorer's order.
--
-- They cannot be recomputed from the other stored rows: the tears, breaks, pull-outs and
-- withdrawn needles they come from are events, which only the recording holds (replaying it
-- needs the lesson's scene and the engine's time). A score stored before this migration was
-- never judged, which is not the same as judged clean: end_product_judged says which.
-- `kind` is endProductErrorKey; stitch, passage and event are 0-based, NULL for none;
-- angle_deg, measured and limit_value NULL where the error has none (NaN).

ALTER TABLE scores ADD COLUMN end_product_judged INTEGER NOT NULL DEFAULT 0 CHECK (end_product_judged IN (0, 1));

CREATE TABLE score_end_product (
  attempt_id   INTEGER NOT NULL REFERENCES scores(attempt_id) ON DELETE CASCADE,
  position     INTEGER NOT NULL,
  kind         TEXT NOT NULL,
  stitch       INTEGER,
  passage      INTEGER,
  event        INTEGER,
  angle_deg    @REAL@,
  measured     @REAL@,
  limit_value  @REAL@,
  PRIMARY KEY (attempt_id, position)
);

@SQLITE@ CREATE TRIGGER score_end_product_no_update BEFORE UPDATE ON score_end_product BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@SQLITE@ CREATE TRIGGER score_end_product_only_in_progress BEFORE INSERT ON score_end_product WHEN (SELECT status FROM attempts WHERE id = NEW.attempt_id) <> 'in_progress' BEGIN SELECT RAISE(ABORT, 'stored scores cannot change'); END;

@POSTGRESQL@ CREATE TRIGGER score_end_product_no_update BEFORE UPDATE ON score_end_product FOR EACH ROW EXECUTE FUNCTION microsim_refuse_score_change();

@POSTGRESQL@ CREATE TRIGGER score_end_product_only_in_progress BEFORE INSERT ON score_end_product FOR EACH ROW EXECUTE FUNCTION microsim_refuse_unless_in_progress();
