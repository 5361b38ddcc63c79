"""cadmedial batch runs on a Dask cluster (see README.md in this folder).

Modules: inputs (which files, where their outputs go), job (one file on a
worker), results (results.jsonl), progress, dask_batch (the driver).
"""
