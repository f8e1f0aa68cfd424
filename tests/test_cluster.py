"""Sweeps and the map's stability boundary on a dask.distributed cluster
(``--scheduler``, ``scheduler=``): the same bytes as a local run, bounded
look-ahead, cancellation, and one line for a missing extra or an
unreachable scheduler.  The cluster is a LocalCluster of two in-process
workers, started once for the module."""

import io
import sys
import time

import pytest

import deathsphere
from deathsphere import cluster
from deathsphere.parallel import ordered_map
from deathsphere.params import ParameterError
from deathsphere.writers.stream import write_csv

distributed = pytest.importorskip("distributed", reason="the distributed extra is not installed")


@pytest.fixture(scope="module")
def client():
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as local, distributed.Client(local) as c:
        yield c


def csv_of(chunks) -> str:
    out = io.StringIO()
    write_csv(chunks, out)
    return out.getvalue()


def test_sweep_on_the_cluster_is_the_local_csv_byte_for_byte(client):
    args = dict(theta="0:180:7.5", alpha="-90:90:7.5", chunk_size=97, only=None)
    local = csv_of(deathsphere.sweep(**args))
    assert csv_of(deathsphere.sweep(**args, scheduler=client)) == local
    # by address too: the command line's way in (a Client of its own, closed at the end)
    assert csv_of(deathsphere.sweep(**args, scheduler=client.scheduler.address)) == local


def test_input_stream_on_the_cluster_is_the_local_csv(client, tmp_path):
    path = tmp_path / "requests.csv"
    path.write_text("theta,alpha,mu\n60,10,1\n60,oops,1\n90,25,0.2\n120,40,\n")
    local = csv_of(deathsphere.orbit_input(str(path), chunk_size=2))
    assert csv_of(deathsphere.orbit_input(str(path), chunk_size=2, scheduler=client)) == local


def test_parquet_from_the_cluster_is_the_local_table(client, tmp_path):
    pq = pytest.importorskip("pyarrow.parquet", reason="Parquet needs pyarrow (the fast extra)")
    from deathsphere.writers.parquet import write_parquet

    args = dict(theta="10:170:20", alpha="5:85:10", chunk_size=11)
    write_parquet(deathsphere.sweep(**args), str(tmp_path / "local.parquet"))
    write_parquet(deathsphere.sweep(**args, scheduler=client), str(tmp_path / "cluster.parquet"))
    assert pq.read_table(tmp_path / "cluster.parquet").equals(pq.read_table(tmp_path / "local.parquet"))


def test_map_stability_boundary_on_the_cluster(client):
    local = deathsphere.region(step=10, stability=True).to_csv()
    assert deathsphere.region(step=10, stability=True, scheduler=client).to_csv() == local


def test_command_line_scheduler_gives_the_local_bytes(client, run):
    args = ["sweep", "--theta", "30:150:15", "--alpha", "0:80:10", "--chunk-size", "13", "--format", "csv"]
    local = run(*args)
    remote = run(*args, "--scheduler", client.scheduler.address)
    assert remote.exit_code == 0 and remote.output == local.output


def test_look_ahead_is_bounded_and_leaving_early_cancels(client):
    drawn = []

    def items():
        for n in range(1000):
            drawn.append(n)
            yield n

    results = ordered_map(abs, items(), 1, client=client)
    assert next(results) == 0
    # two workers, two chunks each in flight: never the whole stream
    assert len(drawn) <= 2 * cluster.AHEAD_PER_WORKER + 1
    results.close()
    # the released tasks leave the scheduler (messages on the client's loop: poll)
    for _ in range(200):
        left = client.run_on_scheduler(lambda dask_scheduler: len(dask_scheduler.tasks))
        if not left:
            break
        time.sleep(0.05)
    assert left == 0


def test_missing_extra_is_one_line_naming_it(monkeypatch, run):
    monkeypatch.setitem(sys.modules, "distributed", None)
    with pytest.raises(ParameterError, match=r"deathsphere\[distributed\]"):
        deathsphere.sweep("10:20:5", 10, scheduler="tcp://127.0.0.1:8786")
    result = run("sweep", "--theta", "10:20:5", "--alpha", "10", "--scheduler", "tcp://127.0.0.1:8786")
    assert result.exit_code == 2 and "deathsphere[distributed]" in result.output
    assert "Traceback" not in result.output


def test_unreachable_scheduler_is_one_line_and_exit_2(monkeypatch, run):
    monkeypatch.setattr(cluster, "CONNECT_TIMEOUT_S", 0.5)
    result = run("sweep", "--theta", "10:20:5", "--alpha", "10", "--scheduler", "tcp://127.0.0.1:1")
    assert result.exit_code == 2 and "cannot reach the dask scheduler" in result.output
    assert "Traceback" not in result.output and len(result.output.strip().splitlines()) == 1


def test_jobs_and_scheduler_together_are_refused(client):
    with pytest.raises(ParameterError, match="not both"):
        deathsphere.sweep("10:20:5", 10, jobs=2, scheduler=client)


def test_command_line_map_stability_on_the_cluster(client, run):
    args = ["map", "--stability", "--step", "10", "--format", "csv"]
    local = run(*args)
    remote = run(*args, "--scheduler", client.scheduler.address)
    assert remote.exit_code == 0 and remote.output == local.output


def test_command_line_map_stability_off_the_globe_on_the_cluster(client, run):
    # the stability boundary's batches of 16 lanes on a drum, on the cluster
    args = ["map", "--surface", "cylinder", "--diameter", "32ft", "--wall-height", "12ft", "--height", "0:3.6:0.2",
            "--stability", "--format", "csv"]
    local = run(*args)
    remote = run(*args, "--scheduler", client.scheduler.address)
    assert remote.exit_code == 0 and remote.output == local.output and "stability," in local.output
