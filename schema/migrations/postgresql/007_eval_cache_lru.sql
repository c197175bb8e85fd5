-- 007_eval_cache_lru: as schema/migrations/007_eval_cache_lru.sql (the cache bounded by
-- --max-cache-mb, least recently used first out).
ALTER TABLE eval_cache ADD COLUMN bytes BIGINT NOT NULL DEFAULT 0;
ALTER TABLE eval_cache ADD COLUMN used BIGINT NOT NULL DEFAULT 0;
UPDATE eval_cache SET bytes = octet_length(result) + COALESCE(octet_length(vdb), 0);
-- Covering (index-only scans for the sum of sizes and the eviction order).
CREATE INDEX eval_cache_used ON eval_cache (used, bytes, key);
