"""A synthesis split into shards and run on Dask's distributed engine
(a local cluster of two worker processes, loopback only) gives the rows
of the same search run in one process, bit for bit."""

import numpy as np
import pyarrow.parquet as pq
import pytest

import linkage
from linkage import shards
from test_synthesis import COUPLER_FOUR_BAR, WORKSHEET, path_bounds, path_targets

SPEC = {"equations": COUPLER_FOUR_BAR, "parameters": WORKSHEET, "name": "CouplerFourBar"}


def task():
    targets = path_targets(5)
    return {"path": "P", "targets": targets.tolist(), "free": path_bounds(targets),
            "precision_points": True, "at": 0.0}


def test_split_covers_the_starts_once():
    pieces = shards.split(SPEC, task(), starts=50, per_shard=16, random_state=9)
    assert [(s.first, s.count) for s in pieces] == [(0, 16), (16, 16), (32, 16), (48, 2)]
    with pytest.raises(ValueError, match="search's own keywords"):
        shards.split(SPEC, {**task(), "starts": 3}, starts=8, per_shard=4)


def test_shards_in_one_process_on_a_cluster_and_retried_are_one_search(tmp_path):
    distributed = pytest.importorskip("distributed")
    pieces = shards.split(SPEC, task(), starts=24, per_shard=8, random_state=3)
    whole = shards.run_shard(shards.Shard(SPEC, task(), 3, 0, 24))
    here = shards.search(pieces)
    assert here.num_rows > 1
    whole = whole.sort_by([("start", "ascending")]).drop_columns(["first"])
    assert here.drop_columns(["first"]).replace_schema_metadata(None).equals(whole.replace_schema_metadata(None))
    assert here.schema.metadata[b"starts"] == b"24"
    # A task run again gives the same rows.
    assert shards.run_shard(pieces[1]).equals(shards.run_shard(pieces[1]))
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  host="127.0.0.1", dashboard_address=None) as cluster:
        with distributed.Client(cluster) as client:
            there = shards.search(pieces, client)
    assert there.equals(here)
    path = tmp_path / "designs.parquet"
    shards.write_parquet(there, path)
    back = pq.read_table(path)
    assert back.equals(here)
    # Every design certified over a turn, through the targets.
    assert (np.asarray(back["largest_error"]) < 1e-9).all()
