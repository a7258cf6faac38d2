"""What converting shapely objects costs flood.check (docs/PYTHON.md, "Inputs").

Usage (from a build): PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/bench_shapely.py [FEATURES]

FEATURES (default 30000) generated polygons of about 8 to 27 vertices (every family whose
polygons are one part without point holes, seeds 1..) are
checked by flood.check on 1 C++ thread three ways: as shapely objects (their WKB, one GEOS
call each: the conversion today), as their ``__geo_interface__`` mappings (a Python tuple per
point, made into numpy arrays ring by ring: the conversion before), and as numpy arrays (no
conversion: the floor). Each figure is the best of 3 runs, wall clock and this process's CPU.
"""

import sys
import time

import shapely
import shapely.geometry as sg

import flood


def best(run, repeat=3):
    wall, cpu = [], []
    for _ in range(repeat):
        w, c = time.perf_counter(), time.process_time()
        run()
        wall.append(time.perf_counter() - w)
        cpu.append(time.process_time() - c)
    return min(wall), min(cpu)


def main():
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 30000
    families = flood.families()
    # One-part polygons whose rings are rings (shapely takes no point hole, as Flood does).
    arrays, i = [], 0
    while len(arrays) < count:
        parts = flood.generate(families[i % len(families)], 8 + i % 20, seed=i + 1)
        i += 1
        if len(parts) == 1 and all(len(r) >= 3 for r in parts[0]):
            arrays.append(parts[0])
    shapes = [sg.Polygon(rings[0], rings[1:]) for rings in arrays]
    mappings = [s.__geo_interface__ for s in shapes]
    vertices = sum(sum(len(r) for r in rings) for rings in arrays)
    print(f"{count} polygons, {vertices / count:.1f} vertices each on average, shapely "
          f"{shapely.__version__}")
    for name, inputs in (("shapely objects (WKB)", shapes),
                         ("__geo_interface__ mappings", mappings),
                         ("numpy arrays", arrays)):
        verdicts = flood.check(inputs, threads=1)
        assert all(v.ok for v in verdicts), [v.message for v in verdicts if not v.ok][:3]
        wall, cpu = best(lambda: flood.check(inputs, threads=1))
        print(f"flood.check, {name}: {wall:.2f} s ({cpu:.2f} CPU s)")


if __name__ == "__main__":
    main()
