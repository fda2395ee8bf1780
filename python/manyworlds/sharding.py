"""Batches sharded over MPI ranks from Python (docs/scale-out.md): the C++
ShardedBatch's rules with mpi4py.

    from mpi4py import MPI
    import manyworlds as mw
    from manyworlds.sharding import ShardedBatch

    batch = ShardedBatch(MPI.COMM_WORLD, mw.make_scene("cartpole"), 1 << 20)
    batch.local.set_body_forces(1, forces[batch.first:batch.first + batch.count])
    batch.step()                                   # collective
    returns = batch.gather(my_returns)             # [total] on rank 0, None elsewhere

Each rank holds the global worlds [first, first + count) (shard_of_worlds:
contiguous, whole blocks of 16) in its own manyworlds.Batch, `local`, which
works as any batch. Collective calls (the constructor, step, gather,
reduce_health) are made by every rank in the same order; a refusal on one
rank raises RankError naming it on every rank, so no rank is left waiting.
mpi4py is imported only by the calls that need it.
"""

import itertools

import numpy as np

from . import _core


class RankError(RuntimeError):
    """A refusal on some rank of a collective call, raised on every rank.
    `rank` is the lowest rank that refused."""

    def __init__(self, rank, message):
        super().__init__(f"rank {rank}: {message}")
        self.rank = rank


def agreed(comm, check):
    """check()'s result on every rank, or RankError on every rank when
    check() raised on any (the lowest failing rank's message): one
    allreduce of an int when none failed, a broadcast of the message after
    a refusal."""
    from mpi4py import MPI
    try:
        result, error = check(), None
    except Exception as e:  # noqa: BLE001 - reported on every rank
        result, error = None, e
    rank, size = comm.Get_rank(), comm.Get_size()
    mine = np.array([rank if error is not None else size], np.int32)
    first = np.empty(1, np.int32)
    comm.Allreduce(mine, first, op=MPI.MIN)
    if first[0] == size:
        return result
    message = comm.bcast(f"{type(error).__name__}: {error}" if rank == first[0] else None,
                         root=int(first[0]))
    raise RankError(int(first[0]), message) from error


def same_on_every_rank(comm, value, describe):
    """Collective: raises RankError on every rank, naming the lowest rank
    whose `value` differs from rank 0's, with describe(its value, rank 0's)
    as the message (one allgather; every rank compares the same list, so all
    raise alike)."""
    values = comm.allgather(value)
    for rank, other in enumerate(values):
        if other != values[0]:
            raise RankError(rank, f"{describe(other, values[0])} (every rank must pass the same)")


class ShardedBatch:
    """num_worlds copies of `scene` over the ranks of `comm` (collective).

    batch_options: the manyworlds.Batch keywords (threads, target) for each
    rank's batch. Raises RankError on every rank when any rank refuses
    (too few worlds for the ranks, a bad scene)."""

    def __init__(self, comm, scene, num_worlds, **batch_options):
        self.comm = comm
        self.rank, self.ranks = comm.Get_rank(), comm.Get_size()
        self.num_worlds = int(num_worlds)

        def build():
            first, count = _core.shard_of_worlds(self.num_worlds, self.rank, self.ranks)
            return first, count, _core.Batch(scene, count, **batch_options)

        self.first, self.count, self.local = agreed(comm, build)

    def shard_of(self, rank):
        """(first, count) of rank `rank`."""
        return _core.shard_of_worlds(self.num_worlds, rank, self.ranks)

    def step(self, *args, **kwargs):
        """Collective local.step(...): every rank's arguments are checked
        (Batch.check_step) before any rank steps, so a refusal on one rank
        (bad settings or arrays) raises RankError on every rank and no world
        has stepped."""
        agreed(self.comm, lambda: self.local.check_step(*args, **kwargs))
        try:
            return self.local.step(*args, **kwargs)
        except BaseException as e:
            # Accepted by the check, failed here alone: the other ranks could
            # not go on without this one.
            import sys
            print(f"manyworlds: ShardedBatch.step failed on rank {self.rank} of {self.ranks} "
                  f"after every rank's check passed: {e!r}; ending every rank", file=sys.stderr,
                  flush=True)
            self.comm.Abort(1)
            raise

    def gather(self, local_values, root=0):
        """Every rank's per-world rows ([count, ...], any dtype, the same row
        shape, dtype and root on every rank) on `root` as [num_worlds, ...] in
        global world order; None on the other ranks. A wrong row count, or a
        row shape, dtype or root unlike rank 0's, raises RankError on every
        rank, naming the rank."""
        values = np.ascontiguousarray(local_values)

        def check():
            if values.ndim < 1 or values.shape[0] != self.count:
                raise ValueError(f"gather: expected {self.count} rows (this rank's worlds), "
                                 f"got shape {values.shape}")
            return values.shape[1:], values.dtype.str

        layout = agreed(self.comm, check)
        same_on_every_rank(self.comm, (layout, root),
                           lambda mine, zero: f"gather: rows {mine[0][0]} of {mine[0][1]} with "
                                              f"root {mine[1]}, rank 0's {zero[0][0]} of "
                                              f"{zero[0][1]} with root {zero[1]}")
        self._check_root(root, "gather")
        from mpi4py import MPI
        row_bytes = values.itemsize * int(np.prod(layout[0], dtype=np.int64))
        out = np.empty((self.num_worlds, *layout[0]), values.dtype) if self.rank == root else None
        if row_bytes == 0:
            return out
        # One datatype per row: counts in rows, so no byte count or offset
        # overflows MPI's int however much root receives.
        row = MPI.BYTE.Create_contiguous(row_bytes).Commit()
        try:
            recv = None
            if self.rank == root:
                counts = [self.shard_of(r)[1] for r in range(self.ranks)]
                displacements = [0, *itertools.accumulate(counts[:-1])]
                recv = [out.view(np.uint8).reshape(-1), counts, displacements, row]
            self.comm.Gatherv([values.view(np.uint8).reshape(-1), self.count, row], recv,
                              root=root)
        finally:
            row.Free()
        return out

    def reduce_health(self, root=0):
        """On root (the same on every rank), {"unhealthy": worlds with any
        health bit, and per bit: "non_finite_state", "velocity_overflow",
        "out_of_range", "non_finite_input", "not_stepped"} over every rank's
        worlds; None elsewhere."""
        from mpi4py import MPI
        same_on_every_rank(self.comm, root,
                           lambda mine, zero: f"reduce_health: root {mine}, rank 0's {zero}")
        self._check_root(root, "reduce_health")
        health = np.asarray(self.local.health)
        local = np.array([np.count_nonzero(health)]
                         + [np.count_nonzero(health & (1 << bit)) for bit in range(5)], np.int64)
        total = np.empty_like(local) if self.rank == root else None
        self.comm.Reduce(local, total, op=MPI.SUM, root=root)
        if self.rank != root:
            return None
        names = ("unhealthy", "non_finite_state", "velocity_overflow", "out_of_range",
                 "non_finite_input", "not_stepped")
        return dict(zip(names, (int(v) for v in total)))

    def _check_root(self, root, call):
        """After same_on_every_rank: the same root everywhere, so all raise."""
        if not 0 <= root < self.ranks:
            raise RankError(0, f"{call}: root {root} is not one of the {self.ranks} ranks")

    def __repr__(self):
        return (f"ShardedBatch(worlds [{self.first}, {self.first + self.count}) of "
                f"{self.num_worlds} on rank {self.rank} of {self.ranks})")


