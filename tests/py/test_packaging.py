"""pulab installs from the repository as a package with a `pulab` command and no dependency.

Offline and without touching the work tree: the sources are copied to a temporary
directory, built into a wheel with the test venv's setuptools (--no-build-isolation),
and the wheel is installed into a fresh venv that has nothing else; its `pulab` command
then runs without PYTHONPATH.
"""
import json
import os
import re
import shutil
import subprocess
import sys

from conftest import ROOT, SEED_INPUT


def _run(cmd, **kw):
    out = subprocess.run(cmd, capture_output=True, text=True, **kw)
    assert out.returncode == 0, (cmd, out.stdout, out.stderr)
    return out


def test_wheel_installs_into_a_bare_venv_and_the_pulab_command_runs(tmp_path):
    src = tmp_path / "src"
    shutil.copytree(ROOT / "py" / "pulab", src / "py" / "pulab",
                    ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
    for name in ("pyproject.toml", "README.md"):
        shutil.copy(ROOT / name, src / name)
    _run([sys.executable, "-m", "pip", "wheel", "-q", "--no-build-isolation", "--no-deps",
          "--no-index", "-w", str(tmp_path / "wheels"), str(src)])
    (wheel,) = (tmp_path / "wheels").glob("pulab-*.whl")
    venv = tmp_path / "venv"
    _run([sys.executable, "-m", "venv", "--without-pip", str(venv)])
    py = venv / "bin" / "python"
    _run([sys.executable, "-m", "pip", "--python", str(py), "install", "-q", "--no-index",
          "--no-deps", str(wheel)])
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    (tmp_path / "seed.json").write_text(json.dumps(SEED_INPUT))
    out = _run([str(venv / "bin" / "pulab"), "report", str(tmp_path / "seed.json")], env=env,
               cwd=tmp_path)
    r = json.loads(out.stdout)
    assert r["vendor"]["Rpm"]["value"] == 15022 and r["vendor"]["LD"]["value"] == 1045
    # The installed package is the one running, and it needs nothing beyond the stdlib.
    where = _run([str(py), "-c", "import pulab; print(pulab.__file__)"], env=env, cwd=tmp_path)
    assert str(venv) in where.stdout
    pkgs = _run([sys.executable, "-m", "pip", "--python", str(py), "list", "--format", "json"])
    assert {p["name"] for p in json.loads(pkgs.stdout)} == {"pulab"}
    # The other subcommands are there too.
    for sub in ("sweep", "batch"):
        _run([str(venv / "bin" / "pulab"), sub, "--help"], env=env)
    bad = subprocess.run([str(venv / "bin" / "pulab"), "report", str(tmp_path / "none.json")],
                         capture_output=True, text=True, env=env)
    assert bad.returncode == 2 and bad.stderr.startswith("error: input: cannot read")


def test_readme_is_short_and_names_what_ci_installs():
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert len(readme.splitlines()) <= 150
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    installed = set()
    for line in ci.splitlines():
        if "apt-get install" in line:
            words = line.split("apt-get install", 1)[1].split(">")[0].split()
            installed |= {w for w in words if not w.startswith("-")} - {"python3-venv"}
    named = set(re.search(r"Debian's `([^`]+)`", readme)[1].split())
    assert installed and named == installed, (named ^ installed)
