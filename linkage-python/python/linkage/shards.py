"""A synthesis larger than one machine, split into deterministic shards.

A shard is a problem, a random state and a range of starts (`first`,
`count`): each start's design depends on the random state and the start's
index alone, and a shard keeps every certified design it finds (designs
found again by later starts included), so the same starts give the same
rows whether they run in one process, on a cluster, or again after a
failed task. `run_shard` is the map task — a plain function of a `Shard`
to an Arrow table, with no engine in it — and `search` maps it over the
shards on whichever engine is given: any object with a `map(function,
items)` returning results or futures (a `dask.distributed.Client`, a
`concurrent.futures` executor), or, without one, this process.

    >>> shards = linkage.shards.split(spec, task, starts=4096, per_shard=256)
    >>> table = linkage.shards.search(shards, client)   # a Dask client
    >>> linkage.shards.write_parquet(table, "designs.parquet")

The table has one row per certified design: `first` (its shard), `start`,
`rms_error`, `largest_error`, the certificate (`certified_from`,
`certified_to`, `transmission`, `transmission_at`) and one column per
parameter of the mechanism, sorted by start.
"""

from dataclasses import dataclass, field
from typing import Any, Mapping, Optional, Sequence

from ._linkage import Mechanism

__all__ = ["Shard", "split", "make", "run_shard", "search", "write_parquet"]


@dataclass(frozen=True)
class Shard:
    """One piece of a search: how to make the mechanism (`spec`: `{"toml":
    text}` for a mechanism or topology file's text, or `{"equations":
    text, "parameters": {...}, "name": name}`), the synthesis (`task`:
    the keywords of `Mechanism.synthesize` other than the search's), the
    random state and the starts `first` to `first + count - 1`."""

    spec: Mapping[str, Any]
    task: Mapping[str, Any]
    random_state: int
    first: int
    count: int
    meta: Mapping[str, Any] = field(default_factory=dict)


SEARCH_KEYWORDS = {"starts", "random_state", "first", "distinct", "none_is_error", "enough"}


def split(spec, task, starts, per_shard, random_state=1):
    """The shards of a search of `starts` starts, `per_shard` each (the
    last takes what is left)."""
    if per_shard < 1 or starts < 1:
        raise ValueError("a search has at least one start, and a shard at least one")
    clash = SEARCH_KEYWORDS & set(task)
    if clash:
        raise ValueError(f"the task gives the search's own keywords: {sorted(clash)}")
    return [
        Shard(spec, task, random_state, first, min(per_shard, starts - first))
        for first in range(0, starts, per_shard)
    ]


def make(spec):
    """The mechanism a spec describes."""
    if "toml" in spec:
        return Mechanism.from_toml(spec["toml"], name=spec.get("name", "<shard>"))
    return Mechanism.from_text(spec["equations"], dict(spec["parameters"]),
                               name=spec.get("name", "Mechanism"))


def run_shard(shard):
    """A shard's certified designs, as an Arrow table (the map task)."""
    import pyarrow as pa

    designs = make(shard.spec).synthesize(
        **dict(shard.task),
        random_state=shard.random_state,
        first=shard.first,
        starts=shard.count,
        distinct=False,
        none_is_error=False,
    )
    columns = {
        "first": pa.array([shard.first] * len(designs), pa.int64()),
        "start": pa.array(designs.start, pa.int64()),
        "rms_error": designs.rms_error,
        "largest_error": designs.largest_error,
        "certified_from": designs.certified_from,
        "certified_to": designs.certified_to,
        "transmission": designs.transmission,
        "transmission_at": designs.transmission_at,
    }
    for k, name in enumerate(designs.parameter_names):
        columns[name] = designs.parameters[:, k]
    table = pa.table(columns)
    return table.replace_schema_metadata({
        "starts": str(designs.starts),
        "failed_starts": str(designs.failed_starts),
        "refused": str(designs.refused),
    })


def search(shards: Sequence[Shard], client: Optional[Any] = None):
    """Every shard's designs, put together and sorted by start. `client`
    maps `run_shard` over the shards (a Dask client, an executor); without
    one they run in this process, one after the other."""
    import pyarrow as pa

    if client is None:
        tables = [run_shard(shard) for shard in shards]
    else:
        results = client.map(run_shard, shards)
        tables = client.gather(results) if hasattr(client, "gather") else list(results)
    if not tables:
        raise ValueError("no shards")
    counts = {"starts": 0, "failed_starts": 0, "refused": 0}
    for table in tables:
        for key in counts:
            counts[key] += int(table.schema.metadata[key.encode()])
    whole = pa.concat_tables([t.replace_schema_metadata(None) for t in tables])
    whole = whole.sort_by([("start", "ascending")])
    return whole.replace_schema_metadata({k: str(v) for k, v in counts.items()})


def write_parquet(table, path):
    """Writes a search's table as Parquet (its counts kept in the file's
    metadata)."""
    import pyarrow.parquet as pq

    pq.write_table(table, path)
