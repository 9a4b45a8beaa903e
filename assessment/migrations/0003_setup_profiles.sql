-- Migration 3: setup profiles (storage/setup_profiles.h). The JSON document holds the
-- whole profile; the other columns are what a list of profiles shows without parsing it.

CREATE TABLE setup_profiles (
  id             @ID@,
  name           TEXT NOT NULL UNIQUE,
  calibrated_by  TEXT NOT NULL DEFAULT '',
  calibrated_at  TEXT NOT NULL,
  fre_mm         @REAL@,
  tre_mm         @REAL@,
  document       TEXT NOT NULL,
  updated_at     TEXT NOT NULL
);
