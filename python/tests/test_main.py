"""`python -m flood` is the flood command (python/flood/__main__.py runs cli::run, linked into
the module): the same bytes written, the same messages, the same exit codes as the CLI, on
valid, invalid, malformed and mistyped input."""
import subprocess
import sys

import pytest

from conftest import INVALID, SAMPLES, SOURCE_DIR


def both(flood_cli, tmp_path, *args, out=None):
    """Runs ARGS through the CLI and through python -m flood; returns both results and, with
    OUT (a file name), both outputs' bytes."""
    results = []
    for side, prog in (("cli", [flood_cli]), ("py", [sys.executable, "-m", "flood"])):
        extra = ["-o", str(tmp_path / f"{side}-{out}")] if out else []
        r = subprocess.run(prog + list(args) + extra, capture_output=True, text=True, timeout=120)
        data = (tmp_path / f"{side}-{out}").read_bytes() if out and r.returncode == 0 else None
        results.append((r, data))
    return results


@pytest.mark.parametrize("path", SAMPLES[:6] + INVALID[:6], ids=lambda p: p.name)
def test_triangulate_as_the_cli(flood_cli, tmp_path, path):
    (cli, cli_out), (py, py_out) = both(flood_cli, tmp_path, "triangulate", str(path), out="t.json")
    assert py.returncode == cli.returncode, (py.stderr, cli.stderr)
    assert py.stderr == cli.stderr
    assert py_out == cli_out


def test_version_help_and_usage_errors(flood_cli, tmp_path):
    (cli, _), (py, _) = both(flood_cli, tmp_path, "--version")
    assert py.returncode == cli.returncode == 0 and py.stdout == cli.stdout
    import flood
    assert py.stdout.strip() == f"flood {flood.__version__}"
    (cli, _), (py, _) = both(flood_cli, tmp_path, "nonesuch")
    assert py.returncode == cli.returncode == 2 and "unknown subcommand" in py.stderr
    (cli, _), (py, _) = both(flood_cli, tmp_path, "triangulate", "--help")
    assert py.returncode == 0 and "Usage: python -m flood triangulate" in py.stdout


def test_stdout_and_exit_codes(flood_cli, tmp_path):
    (cli, _), (py, _) = both(flood_cli, tmp_path, "transcript", str(SOURCE_DIR / "polygons" /
                                                                    "paper-figure-7.json"))
    assert py.returncode == cli.returncode == 0 and py.stdout == cli.stdout and py.stdout
    (cli, _), (py, _) = both(flood_cli, tmp_path, "check", str(SOURCE_DIR / "polygons" / "invalid"))
    assert py.returncode == cli.returncode == 4
    assert py.stdout.splitlines()[-1].split(";")[0] == cli.stdout.splitlines()[-1].split(";")[0]
    (cli, _), (py, _) = both(flood_cli, tmp_path, "triangulate", str(tmp_path / "missing.json"))
    assert py.returncode == cli.returncode == 3 and py.stderr == cli.stderr


def test_main_returns_the_exit_code(tmp_path, capfd):
    from flood.__main__ import main
    bowtie = tmp_path / "bowtie.json"
    bowtie.write_text("[[[0,0],[4,4],[4,0],[0,4]]]")
    assert main(["triangulate", str(bowtie), "-o", str(tmp_path / "o.json")]) == 4
    assert "bowtie.json" in capfd.readouterr().err
    assert not (tmp_path / "o.json").exists()
