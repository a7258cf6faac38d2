"""Throughput of flood.check and what Dask adds per feature (docs/BENCHMARKS.md, "Python").

Usage (from a build): PYTHONPATH=build/python python3 python/benchmarks/bench_check.py [FEATURES] [SIZE]

The same FEATURES generated features of about SIZE vertices each, as WKT strings (what a
dataset export gives), are checked (read, validated, flooded, checked exactly) by
flood.check on 1 and 2 C++ threads, then by flood.dask on a local cluster of 2 worker
processes (1 thread each). Each figure is the best of 3 runs, wall clock; the CPU seconds of
this process are printed beside flood.check's (on a loaded machine threads wait for a core,
which wall clock counts and CPU time does not). Dask's overhead is counted in CPU seconds too:
this process (client and scheduler) plus both workers, against flood.check's. Each Dask round numbers the features from a
new offset, so its graph is new: Dask would otherwise hand back the previous round's results.
"""

import sys
import time

import dask.bag as db
import distributed

import flood
import flood.dask


def wkt(parts):
    def ring(a):
        return "(" + ", ".join(f"{x!r} {y!r}" for x, y in list(a) + [a[0]]) + ")"
    return "MULTIPOLYGON (" + ", ".join("(" + ", ".join(ring(r) for r in rings) + ")"
                                        for rings in parts) + ")"


def best(run, repeat=3):
    """Best wall and CPU seconds of `repeat` calls of run(round)."""
    wall, cpu = [], []
    for r in range(repeat):
        w, c = time.perf_counter(), time.process_time()
        run(r)
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    return min(wall), min(cpu)


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    size = int(sys.argv[2]) if len(sys.argv) > 2 else 64
    families = flood.families()
    features = [wkt(flood.generate(families[i % len(families)], size, seed=i)) for i in range(count)]
    vertices = sum(len(f.split(",")) for f in features)
    print(f"{count} features, {vertices / count:.0f} WKT points each on average")

    direct, direct_cpu = {}, {}
    for threads in (1, 2):
        direct[threads], direct_cpu[threads] = best(lambda r: flood.check(features, threads=threads))
        cpu = direct_cpu[threads]
        print(f"flood.check, {threads} thread(s): {direct[threads]:.3f} s, "
              f"{count / direct[threads]:,.0f} features/s ({cpu:.3f} CPU s)")

    with distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1,
                                  dashboard_address=None) as cluster, distributed.Client(cluster) as client:
        # The data on the workers first: the check is timed, not the upload.
        bags = [db.from_sequence([(r * count + i, f) for i, f in enumerate(features)],
                                 npartitions=16).persist() for r in range(3)]
        distributed.wait(bags)
        worker_cpu = []

        def run(r):
            before = sum(client.run(time.process_time).values())
            flood.dask.failures(bags[r])
            worker_cpu.append(sum(client.run(time.process_time).values()) - before)

        dask_time, local_cpu = best(run)
    dask_cpu = local_cpu + min(worker_cpu)
    print(f"flood.dask, 2 worker processes, 16 partitions: {dask_time:.3f} s, "
          f"{count / dask_time:,.0f} features/s ({dask_cpu:.3f} CPU s, workers and client)")
    print(f"Dask overhead per feature: {(dask_cpu - direct_cpu[1]) / count * 1e6:.1f} CPU us "
          f"(flood.check itself: {direct_cpu[1] / count * 1e6:.1f} CPU us per feature)")


if __name__ == "__main__":
    main()
