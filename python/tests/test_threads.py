"""The module under threads: Python threads (the GIL is released in the core) and check()'s
own C++ threads give exactly the serial results; Ctrl+C stops a long check()."""
from concurrent.futures import ThreadPoolExecutor

import pytest

import flood
from conftest import SAMPLES


def polygons():
    texts = [p.read_text() for p in SAMPLES]
    generated = [flood.generate(f, 400, seed) for f in flood.families() for seed in (1, 2)]
    return texts + generated


def test_thread_pool_equals_serial():
    inputs = polygons()
    serial = [flood.triangulate(p).triangles.tolist() for p in inputs]
    with ThreadPoolExecutor(max_workers=8) as pool:
        threaded = list(pool.map(lambda p: flood.triangulate(p).triangles.tolist(), inputs * 2))
    assert threaded == serial * 2


def test_check_on_threads_equals_one_at_a_time():
    inputs = polygons() + [[(0, 0), (10, 10), (10, 0), (0, 12)]]  # one bow-tie
    one = flood.check(inputs, threads=1)
    many = flood.check(inputs, threads=4)
    assert many == one
    assert [v.triangles for v in one[:-1]] == [len(flood.triangulate(p).triangles) for p in inputs[:-1]]
    assert [v.ok for v in one] == [True] * (len(inputs) - 1) + [False]
    assert one[-1].index == len(inputs) - 1 and one[-1].message.startswith(f"feature {len(inputs) - 1}: ring 0")


def test_the_gil_is_released_while_the_core_runs():
    """With a switch interval longer than the call, a Python thread runs during a core call
    only if the call lets go of the GIL: the counter moves between the worker's two reads."""
    import sys
    import threading
    import time

    polygon = flood.generate("circle-holes", 100000, 1)
    counter, done, started, reads = [0], threading.Event(), threading.Event(), []

    def worker():
        started.set()
        reads.append(counter[0])
        flood.triangulate(polygon)
        reads.append(counter[0])
        done.set()

    interval = sys.getswitchinterval()
    sys.setswitchinterval(30)
    try:
        thread = threading.Thread(target=worker)
        thread.start()
        started.wait()
        while not done.is_set():
            counter[0] += 1
            time.sleep(0)  # lets the worker have the GIL back when it asks
        thread.join()
    finally:
        sys.setswitchinterval(interval)
    assert reads[1] > reads[0]


@pytest.mark.parametrize("threads", [1, 2])
def test_ctrl_c_stops_check_between_features(threads):
    """SIGINT during a long check() raises KeyboardInterrupt after the feature being flooded,
    not when the whole call would have ended (issue 25 item 10: 9 s later)."""
    import signal
    import threading
    import time

    polygon = flood.generate("circle-holes", 4000, 1)
    start = time.perf_counter()
    flood.check([polygon] * 8, threads=1)
    per_feature = (time.perf_counter() - start) / 8
    count = max(64, int(4.0 / per_feature))  # about 4 s of flooding on one thread
    whole = count * per_feature / threads
    handler = signal.signal(signal.SIGINT, signal.default_int_handler)
    main, sent = threading.main_thread().ident, []

    def interrupt():
        sent.append(time.perf_counter())
        signal.pthread_kill(main, signal.SIGINT)

    timer = threading.Timer(0.2, interrupt)
    try:
        timer.start()
        with pytest.raises(KeyboardInterrupt):
            flood.check([polygon] * count, threads=threads)
        latency = time.perf_counter() - sent[0]
    finally:
        timer.cancel()
        signal.signal(signal.SIGINT, handler)
    assert latency < whole / 4, f"{latency:.2f} s to stop a check of about {whole:.2f} s"
    assert flood.check([polygon], threads=threads)[0].ok  # the next call runs as usual
