"""Writers of result tables: CSV, JSON and NDJSON streamed chunk by chunk
(:mod:`~deathsphere.writers.stream`), CSV compiled in polars
(:mod:`~deathsphere.writers.polars_csv`) and Parquet through pyarrow
(:mod:`~deathsphere.writers.parquet`), both from the ``fast`` extra."""
