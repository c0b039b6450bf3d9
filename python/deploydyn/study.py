"""Load-case and sampled studies from Python, as `deploydyn study` runs them, alone or over MPI
through mpi4py (docs/model-format.md, "Load-case studies", "Studies over MPI").

    import deploydyn
    cases = deploydyn.run_study("examples/paper/general_study.yaml", out="results/general")

    # study.py, started as `mpirun -n 4 python3 study.py`:
    from mpi4py import MPI
    cases = deploydyn.run_study("study.yaml", out="results/s", comm=MPI.COMM_WORLD)
    # process 0 returns the cases; the others return None

The case folders and study.csv are those of `deploydyn study` (and of `mpirun -n N deploydyn
study`): the same C++ runner decides which process runs which case (the next free one), and
process 0 alone writes study.csv and study.json.
"""
import os
import socket
import sys
import traceback

from deploydyn import _arguments as checked
from deploydyn import _core
from deploydyn._overrides import override_pairs

# The tags of the two messages, as app/mpi_channel.cpp uses them over MPI's C API.
_REPORT_TAG = 1
_ASSIGN_TAG = 2


class _Mpi4pyChannel(_core.StudyChannel):
    """The study channel (study/study_channel.hpp) over an mpi4py communicator. Every call
    comes from the thread that called run_study, which holds the GIL for it."""

    def __init__(self, comm):
        super().__init__()
        from mpi4py import MPI  # noqa: only needed here; a serial study does without mpi4py
        self._mpi = MPI
        self._comm = comm
        self.lost_ranks = []
        # Who every process is, for process 0 to watch from the start (collective).
        self._identities = comm.gather((os.getpid(), socket.gethostname()), root=0)

    def rank(self):
        return self._comm.Get_rank()

    def size(self):
        return self._comm.Get_size()

    def poll_report(self):
        status = self._mpi.Status()
        if not self._comm.iprobe(source=self._mpi.ANY_SOURCE, tag=_REPORT_TAG, status=status):
            return None
        fields = self._comm.recv(source=status.Get_source(), tag=_REPORT_TAG)
        report = _core.WorkerReport()
        report.rank = status.Get_source()
        for name, value in fields.items():
            setattr(report, name, value)
        return report

    def assign(self, rank, case_index):
        self._comm.send(case_index, dest=rank, tag=_ASSIGN_TAG)

    def report_and_wait(self, report):
        fields = {name: getattr(report, name)
                  for name in ("finished_case", "status", "ran", "message", "pid", "host")}
        self._comm.send(fields, dest=0, tag=_REPORT_TAG)
        return self._comm.recv(source=0, tag=_ASSIGN_TAG)

    def identity(self, rank):
        return tuple(self._identities[rank]) if self._identities else None

    def lost(self, rank):
        self.lost_ranks.append(rank)

    def free(self):
        self._comm.Free()


def run_study(file, out=None, jobs=None, resume=False, comm=None, stop=None, overrides=None):
    """Runs the study file `file` as `deploydyn study FILE` does: each case into its folder
    under `out` (default: the study file's `out`, else results/<study name>), then study.csv.
    `jobs`: cases at once in this process (default: the study's `jobs`; all at once alone, one
    per process over MPI). `resume`: keep the cases an earlier run completed for the same model.
    `comm`: an mpi4py communicator (e.g. MPI.COMM_WORLD) when the script runs under `mpirun
    -n N`: the N processes share the cases, each takes the next one when it is free.
    `overrides` (as `load` takes them: a dict {path: value}, "PATH=VALUE" texts) change the
    model of every case before the case's own overrides, as `deploydyn study --set` does.

    Returns, in process 0 (or alone), one dict per case in the study's order: name, status
    ("completed", "failed", "interrupted"), message, process (the one that ran it), resumed,
    folder; in the other processes None. Bad input raises InputError; a folder in use or a
    study.csv that cannot be written raises OutputError; failed cases do not raise (their
    status says so), as the command's exit code 1. Over MPI, an error in any process, or a
    process that died (mpirun --enable-recovery), ends every process with MPI_Abort once what
    could be written is written: study.json then tells what happened.

    Ctrl-C (alone, not over MPI) stops the running cases within a fraction of a second, as
    `stop` (a threading.Event, for a study in another thread) does once set: they end
    "interrupted", the cases not started are listed as such, study.csv and study.json are
    written, and the finished cases stay in their folders; then Ctrl-C raises
    KeyboardInterrupt, `stop` returns the cases."""
    where = "run_study"
    file = checked.path(where, "file", file)
    folder = None if out is None else checked.path(where, "out", out)
    if jobs is not None:
        jobs = checked.count(where, "jobs", jobs, minimum=0)
    if not isinstance(resume, bool):
        raise TypeError(f"{where}: resume must be a bool, not {checked.shown(resume)}")
    if comm is not None and not all(hasattr(comm, name) for name in ("Get_rank", "Get_size", "Dup")):
        raise TypeError(f"{where}: comm must be an mpi4py communicator (e.g. MPI.COMM_WORLD) or "
                        f"None, not {checked.shown(comm)}")
    stop = checked.stop(where, stop)
    # A communicator of the study's own (collective: every process calls run_study), so that
    # the script's own messages cannot be taken for the study's.
    channel = _Mpi4pyChannel(comm.Dup()) if comm is not None and comm.Get_size() > 1 else None
    try:
        cases = _core.run_study(file, folder, -1 if jobs is None else jobs, resume, channel, stop,
                                override_pairs(where, overrides))
    except BaseException:
        # The other processes may be waiting for this one: end them all rather than hang, as
        # `deploydyn study` does (the error is printed first; mpirun exits non-zero).
        if channel is not None:
            traceback.print_exc()
            sys.stderr.flush()
            comm.Abort(2)
        raise
    if channel is not None and channel.lost_ranks:
        # MPI cannot finish normally with a dead member: as `deploydyn study` does, end the
        # others now that every result is written (so process 0 returns nothing either).
        print(f"process {', '.join(map(str, channel.lost_ranks))} died; its case is listed as failed and "
              "every other result is written; ending the other processes (MPI_Abort)", file=sys.stderr,
              flush=True)
        comm.Abort(1)
    if channel is not None:
        channel.free()
    return cases

