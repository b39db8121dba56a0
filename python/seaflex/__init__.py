"""seaflex: flexible multibody dynamics of offshore structures (Python package).

seaflex.batch runs load-case batches with the command-line executable on dask.distributed.
"""
