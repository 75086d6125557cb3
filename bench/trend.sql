-- The trend table of `axcheck trend` (the Theil–Sen slope per year of each series) in SQL,
-- for a history larger than one machine holds: DuckDB runs it where the history lies
-- (other engines need QUALIFY as a subquery and their own median). Series as axcheck forms
-- them: machine, serial (absent: empty) and axis; per date the axis's first test that has
-- the parameter, the mean over the campaigns of one date. bench/duckdb_trend.py compares it
-- with `axcheck trend --json`.
WITH r AS (
  SELECT machine, coalesce(serial, '') AS serial, axis, parameter, "date", test, value
  FROM read_parquet('history/**/*.parquet', hive_partitioning = true)
  QUALIFY test = min(test) OVER (PARTITION BY machine, serial, axis, parameter, "date")
), h AS (
  SELECT machine, serial, axis, parameter, "date", avg(value) AS value
  FROM r
  GROUP BY ALL
), pairs AS (
  SELECT a.machine, a.serial, a.axis, a.parameter,
         (b.value - a.value) / (datediff('day', a."date", b."date") / 365.25) AS slope
  FROM h AS a JOIN h AS b USING (machine, serial, axis, parameter)
  WHERE b."date" > a."date"
)
SELECT machine, serial, axis, parameter, median(slope) AS slope_per_year
FROM pairs
GROUP BY ALL
ORDER BY ALL;
