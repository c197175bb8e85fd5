-- 007_eval_cache_lru: the evaluation cache is bounded (fsdb serve --max-cache-mb) and evicts the
-- least recently used entries first. bytes is the size of an entry (result and grid); used the
-- last time it was stored or read (ms since 1970, refreshed at most every 10 s per entry).
-- Before, every new request (alpha=0.400001, 0.400002, ...) cached a mesh for ever.
ALTER TABLE eval_cache ADD COLUMN bytes INTEGER NOT NULL DEFAULT 0;
ALTER TABLE eval_cache ADD COLUMN used INTEGER NOT NULL DEFAULT 0;
UPDATE eval_cache SET bytes = length(CAST(result AS BLOB)) + COALESCE(length(vdb), 0);
-- Covering: the sum of sizes and the eviction order read the index, not every cached grid (bytes
-- is stored after the blobs in a row, so reading it from the table reads them).
CREATE INDEX eval_cache_used ON eval_cache (used, bytes, key);
