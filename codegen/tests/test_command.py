"""The command `armdyn-codegen` (the same as ``python3 -m armdyn_codegen``; ``pip install
./codegen`` installs it): the registry's bytes for the registry's robots, an invalid
description refused with nothing written, the registry upkeep of ``codegen/regenerate.sh``
(``--check``, ``--index-only``, ``--prune``), and an install into a scratch venv whose command
writes the same bytes.

Only planar2 and the SCARA are derived here (seconds each); the URDF robots and the PUMA 560
are left to the drift check of CI."""

import os
import shutil
import subprocess
import sys
import tomllib
from importlib import metadata
from pathlib import Path

import pytest

from test_bad_descriptions import CASES as DH_CASES
from test_urdf import CASES as URDF_CASES

ROOT = Path(__file__).resolve().parents[2]
SMALL = ("planar2", "scara")
ROBOTS = sorted(p.relative_to(ROOT).as_posix() for p in (ROOT / "robots").glob("*.toml"))


def _command(*args, cwd=ROOT):
    """The in-tree command, from the repository root by default (so that the graphs name their
    description as the registry's do, `robots/<name>.toml`)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT / "codegen"))
    return subprocess.run([sys.executable, "-m", "armdyn_codegen", *map(str, args)],
                          capture_output=True, text=True, env=env, cwd=cwd, timeout=300)


def _registry(*names):
    """{file name: bytes} of the committed outputs of these robots: the two graphs
    (generated/models) and the URDF (generated/urdf)."""
    files = {}
    for n in names:
        for stem in (n, f"{n}_parametric"):
            files[f"{stem}.json"] = (ROOT / "generated" / "models" / f"{stem}.json").read_bytes()
        files[f"{n}.urdf"] = (ROOT / "generated" / "urdf" / f"{n}.urdf").read_bytes()
    return files


def _assert_same_files(folder, expected):
    got = {p.name: p.read_bytes() for p in sorted(folder.iterdir())}
    assert sorted(got) == sorted(expected)
    for name, data in expected.items():
        assert got[name] == data, f"{folder / name} differs from the committed {name}"


def test_the_command_writes_the_registrys_bytes(tmp_path):
    out = tmp_path / "out"
    proc = _command(*(f"robots/{n}.toml" for n in SMALL), "--out", out, "--quiet")
    assert proc.returncode == 0, proc.stderr
    # Exactly the two graphs and the URDF of each robot, byte for byte the registry's.
    _assert_same_files(out, _registry(*SMALL))
    # Written again: kept (the graphs record the current hashes), nothing touched.
    proc = _command("robots/planar2.toml", "--out", out, "--quiet")
    assert proc.returncode == 0, proc.stderr
    assert "planar2 (robots/planar2.toml): unchanged (description and generator), kept" in proc.stdout
    _assert_same_files(out, _registry(*SMALL))


def test_urdf_and_c_folders(tmp_path):
    models, urdf, c = tmp_path / "models", tmp_path / "urdf", tmp_path / "c"
    proc = _command("robots/planar2.toml", "--out", models, "--urdf-out", urdf, "--c-out", c)
    assert proc.returncode == 0, proc.stderr
    expected = _registry("planar2")
    _assert_same_files(models, {k: v for k, v in expected.items() if k.endswith(".json")})
    _assert_same_files(urdf, {"planar2.urdf": expected["planar2.urdf"]})
    _assert_same_files(c, {"planar2.c": (ROOT / "generated/casadi_c/planar2.c").read_bytes()})
    for path in (models / "planar2.json", models / "planar2_parametric.json", urdf / "planar2.urdf"):
        assert f"wrote {path} (sha256 " in proc.stdout


def _write_bad(tmp_path, case):
    """(description, [what the message must contain]) of one invalid description."""
    if case == "dh-negative-mass":
        text, needles = DH_CASES["negative-mass"]
        desc = tmp_path / "planar2.toml"
        desc.write_text(text)
        return desc, needles
    urdf_text, toml_text, needles = URDF_CASES["broken-chain"]
    (tmp_path / "urdf").mkdir()
    (tmp_path / "urdf" / "panda.urdf").write_text(urdf_text)
    desc = tmp_path / "panda.toml"
    desc.write_text(toml_text)
    return desc, needles + [str(tmp_path / "urdf" / "panda.urdf"), "tip"]


@pytest.mark.parametrize("check", [False, True], ids=["generate", "check"])
@pytest.mark.parametrize("case", ["dh-negative-mass", "urdf-broken-chain"])
def test_an_invalid_description_is_named_and_nothing_is_written(tmp_path, case, check):
    desc, needles = _write_bad(tmp_path, case)
    out = tmp_path / "models"
    # A valid description beside it: still nothing is written.
    args = ["robots/scara.toml", desc, "--out", out, "--urdf-out", tmp_path / "urdf-out"]
    proc = _command(*args, *(["--check"] if check else []))
    assert proc.returncode == 1, proc.stderr
    assert f"error: {desc}: " in proc.stderr, proc.stderr
    for needle in needles:
        assert needle in proc.stderr, f"{needle!r} not in:\n{proc.stderr}"
    assert proc.stderr.rstrip().endswith("error: nothing written"), proc.stderr
    assert "Traceback" not in proc.stderr
    assert not out.exists() and not (tmp_path / "urdf-out").exists()


def test_check_validates_everything_and_writes_nothing(tmp_path):
    proc = _command("--check", "--out", "generated/models", *ROBOTS)
    assert proc.returncode == 0, proc.stderr
    assert f"checked {len(ROBOTS)} description(s): no errors (nothing written)" in proc.stdout
    # The task is checked too, on the Jacobian the generator would export.
    text = (ROOT / "robots/planar2.toml").read_text().replace('task = ["x", "y"]', 'task = ["x", "z"]')
    (tmp_path / "planar2.toml").write_text(text)
    proc = _command("--check", tmp_path / "planar2.toml", cwd=tmp_path)
    assert proc.returncode == 1
    assert "`task` = [x, z]: the Jacobian's rows for these directions have rank at most 1 < 2" in proc.stderr
    assert list(tmp_path.iterdir()) == [tmp_path / "planar2.toml"]


def test_index_only_writes_the_registry_and_prunes(tmp_path):
    index = tmp_path / "src" / "models.rs"
    proc = _command("--index-only", "--rust-index", index, *ROBOTS)
    assert proc.returncode == 0, proc.stderr
    assert index.read_bytes() == (ROOT / "generated/src/models.rs").read_bytes()
    # --prune removes the files of robots that are not given, and only those.
    models = tmp_path / "models"
    models.mkdir()
    for name, data in _registry(*SMALL).items():
        (models / name).write_bytes(data)
    (models / "notes.txt").write_text("kept")
    proc = _command("--index-only", "--prune", "--out", models, "robots/planar2.toml")
    assert proc.returncode == 0, proc.stderr
    assert sorted(p.name for p in models.iterdir()) == [
        "notes.txt", "planar2.json", "planar2.urdf", "planar2_parametric.json"]
    assert f"removed stale {models / 'scara.json'}" in proc.stdout
    # The index of a robot whose graphs are not there is refused, and not written.
    proc = _command("--index-only", "--rust-index", tmp_path / "other.rs", "--out", models,
                    "robots/scara.toml")
    assert proc.returncode == 1
    assert f"{models / 'scara.json'} does not exist: generate the robot first" in proc.stderr
    assert not (tmp_path / "other.rs").exists()


def test_a_renamed_robot_frees_its_model_files_for_another_description(tmp_path):
    """One description per call, as codegen/regenerate.sh runs them: once a.toml names another
    robot, the model it wrote before is stale, and b.toml may take over its name."""
    planar2 = (ROOT / "robots/planar2.toml").read_text()
    (tmp_path / "a.toml").write_text(planar2)
    out = tmp_path / "out"
    assert _command("a.toml", "--out", out, "--quiet", cwd=tmp_path).returncode == 0
    (tmp_path / "b.toml").write_text(planar2.replace("mass = 2.0", "mass = 3.0"))
    proc = _command("b.toml", "--out", out, "--quiet", cwd=tmp_path)
    assert proc.returncode == 1
    assert "robot name `planar2` would overwrite" in proc.stderr and "the model of a.toml" in proc.stderr
    (tmp_path / "a.toml").write_text(planar2.replace('name = "planar2"', 'name = "planar2_a"'))
    proc = _command("b.toml", "--out", out, "--quiet", cwd=tmp_path)
    assert proc.returncode == 0, proc.stderr


def _pins(lines):
    return {line.split("==")[0].strip().lower(): line.split("==")[1].split("#")[0].strip()
            for line in lines if "==" in line and not line.lstrip().startswith("#")}


def test_installed_dependencies_are_pinned_as_in_requirements():
    project = tomllib.loads((ROOT / "codegen/pyproject.toml").read_text())["project"]
    requirements = _pins((ROOT / "codegen/requirements.txt").read_text().splitlines())
    runtime = _pins(project["dependencies"])
    assert sorted(runtime) == ["casadi", "lxml", "mpmath", "numpy", "pyyaml", "sympy",
                               "urdf-parser-py"]
    assert {k: requirements[k] for k in runtime} == runtime
    assert project["scripts"] == {"armdyn-codegen": "armdyn_codegen.cli:main_command"}


def _local_build_backend() -> bool:
    """Whether this Python can build the package without downloading: setuptools >= 61 (the
    pyproject.toml metadata) with its own bdist_wheel (70.1) or the `wheel` package."""
    from packaging.version import Version

    try:
        setuptools = Version(metadata.version("setuptools"))
    except metadata.PackageNotFoundError:
        return False
    if setuptools < Version("61"):
        return False
    try:
        metadata.version("wheel")
        return True
    except metadata.PackageNotFoundError:
        return setuptools >= Version("70.1")


@pytest.mark.slow
def test_pip_install_gives_a_command_that_writes_the_same_bytes(tmp_path):
    """`pip install` of a copy of codegen/ (pip builds in the source folder: build/ and
    *.egg-info stay out of the tree) into a venv that sees this Python's packages (CasADi & co.,
    so nothing but perhaps the build backend is downloaded); its `armdyn-codegen` writes the
    registry's bytes and records the in-tree generator's hash."""
    src = tmp_path / "src"
    src.mkdir()
    shutil.copy2(ROOT / "codegen" / "pyproject.toml", src)
    shutil.copytree(ROOT / "codegen" / "armdyn_codegen", src / "armdyn_codegen",
                    ignore=shutil.ignore_patterns("__pycache__"))
    venv = tmp_path / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--system-site-packages", venv], check=True,
                   timeout=120)
    python, command = venv / "bin" / "python", venv / "bin" / "armdyn-codegen"
    env = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
    install = [python, "-m", "pip", "install", "--quiet", "--disable-pip-version-check", "--no-deps"]
    if _local_build_backend():
        install.append("--no-build-isolation")
    proc = subprocess.run([*install, src], capture_output=True, text=True, env=env, timeout=300)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    where = subprocess.run([python, "-c", "import armdyn_codegen; print(armdyn_codegen.__file__)"],
                           capture_output=True, text=True, env=env, cwd=ROOT, check=True)
    assert Path(where.stdout.strip()).is_relative_to(venv), where.stdout
    # The installed copy hashes as the tree does (the same modules, nothing more).
    installed = subprocess.run([command, "--version"], capture_output=True, text=True, env=env,
                               check=True).stdout
    assert installed == _command("--version").stdout
    out = tmp_path / "out"
    proc = subprocess.run([command, "robots/planar2.toml", "--out", out, "--quiet"],
                          capture_output=True, text=True, env=env, cwd=ROOT, timeout=300)
    assert proc.returncode == 0, proc.stderr
    _assert_same_files(out, _registry("planar2"))
