"""Never lose or corrupt a user's files: owned directories, special files,
full disks, kills and signals, one-line errors.

References: the file system itself (what is on disk before and after, byte for byte),
OpenColorIO loading the config that is left behind (``Config.CreateFromFile`` and a
processor for every colour space and view, which parses every LUT file), POSIX exit
statuses (128 + signal number) and the CLI contract (one line on stderr, exit 2).
"""

from __future__ import annotations

import errno
import os
import random
import signal
import stat
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from ocio_thinfilm import io
from ocio_thinfilm.cli import main as cli
from ocio_thinfilm.io import durable
from ocio_thinfilm.io import temporaries as io_temporaries

ROOT = Path(__file__).resolve().parents[1]
CONFIG_DIR = ROOT / "configs" / "thinfilm"


def snapshot(directory) -> dict:
    """Every entry under ``directory`` -> its bytes (files) or a type tag."""
    out = {}
    for p in sorted(Path(directory).rglob("*")):
        rel = p.relative_to(directory).as_posix()
        if p.is_symlink():
            out[rel] = ("link", os.readlink(p))
        elif p.is_file():
            out[rel] = p.read_bytes()
        else:
            out[rel] = "dir"
    return out


def temporaries(*directories) -> list:
    return [
        p
        for d in directories
        if Path(d).exists()
        for p in Path(d).rglob("*")
        if p.name.startswith(io.TMP_PREFIX)
    ]


def cli_run(argv, capsys):
    code = cli.main(argv)
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def one_line_error(code, err, *needles):
    lines = [line for line in err.splitlines() if line.strip()]
    assert code == 2, err
    assert len(lines) == 1, err
    assert "error:" in lines[0] and lines[0].startswith("ocio-thinfilm"), err
    for needle in needles:
        assert needle in lines[0], (needle, err)


def config_loads(directory) -> None:
    """OpenColorIO loads the config and builds every processor (reading every LUT)."""
    import PyOpenColorIO as ocio

    ocio.ClearAllCaches()
    config = ocio.Config.CreateFromFile(str(Path(directory) / "config.ocio"))
    config.validate()
    for name in config.getColorSpaceNames():
        config.getProcessor(name, "CIE-XYZ-D65").getDefaultCPUProcessor()
    for display in config.getDisplays():
        for view in config.getViews(display):
            config.getProcessor(
                "CIE-XYZ-D65", display, view, ocio.TRANSFORM_DIR_FORWARD
            ).getDefaultCPUProcessor()


def marker_files(directory) -> set:
    lines = (Path(directory) / io.MARKER).read_text().splitlines()
    return {line for line in lines if line and not line.startswith("#")}


def files_under(directory) -> set:
    """Files under ``directory`` but the marker and the temporaries of a killed run."""
    return {
        p.relative_to(directory).as_posix()
        for p in Path(directory).rglob("*")
        if p.is_file()
        and p.name != io.MARKER
        and not any(part.startswith(io.TMP_PREFIX) for part in p.relative_to(directory).parts)
    }


# --------------------------------------------------------------------------- #
# Owned directories: a bake never destroys what it did not create
# --------------------------------------------------------------------------- #
def test_bake_refuses_a_directory_holding_a_users_files(tmp_path, capsys):
    shots = tmp_path / "shots"
    shots.mkdir()
    (shots / "plate.exr").write_bytes(b"user data")
    (shots / "sub").mkdir()
    before = snapshot(tmp_path)
    for argv in (
        ["bake", "--out", str(shots)],
        ["bake", "--out", str(tmp_path / "cfg"), "--luts", str(shots)],
    ):
        code, _, err = cli_run(argv + ["--quiet", "--clip-size", "9"], capsys)
        one_line_error(code, err, str(shots), "not written by ocio-thinfilm")
        assert snapshot(tmp_path) == before


def test_bake_luts_into_a_users_file_is_refused(tmp_path, capsys):
    user = tmp_path / "notes.txt"
    user.write_text("mine")
    code, _, err = cli_run(
        [
            "bake",
            "--out",
            str(tmp_path / "cfg"),
            "--luts",
            str(user),
            "--quiet",
            "--clip-size",
            "9",
        ],
        capsys,
    )
    one_line_error(code, err, "--luts", "not a directory")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["notes.txt"]
    assert user.read_text() == "mine"


@pytest.mark.parametrize("out", ["", " "])
def test_bake_out_empty_is_a_one_line_error(tmp_path, capsys, monkeypatch, out):
    monkeypatch.chdir(tmp_path)
    code, _, err = cli_run(["bake", "--out", out, "--quiet"], capsys)
    one_line_error(code, err, "--out")
    assert list(tmp_path.iterdir()) == []


def test_rebake_replaces_only_its_own_files(tmp_path, capsys):
    cfg = tmp_path / "cfg"
    assert cli_run(["bake", "--out", str(cfg), "--quiet", "--clip-size", "9"], capsys)[0] == 0
    first = files_under(cfg)
    assert marker_files(cfg) == first and "config.ocio" in first
    (cfg / "notes.txt").write_text("the user's")
    (cfg / "luts" / "mine.clf").write_text("the user's LUT")
    # a file the previous run listed but this one does not write: removed
    (cfg / "luts" / "Obsolete.clf").write_text("<ProcessList/>")
    with open(cfg / io.MARKER, "a") as f:
        f.write("luts/Obsolete.clf\n")
    old_clip = (cfg / "luts" / "ConstantLightnessClip_sRGB_BlackFaces.clf").read_bytes()
    assert cli_run(["bake", "--out", str(cfg), "--quiet", "--clip-size", "10"], capsys)[0] == 0
    assert (cfg / "notes.txt").read_text() == "the user's"
    assert (cfg / "luts" / "mine.clf").read_text() == "the user's LUT"
    assert not (cfg / "luts" / "Obsolete.clf").exists()
    assert (cfg / "luts" / "ConstantLightnessClip_sRGB_BlackFaces.clf").read_bytes() != old_clip
    assert marker_files(cfg) == first
    assert temporaries(tmp_path) == []
    config_loads(cfg)


def test_the_committed_outputs_carry_their_markers(tmp_path, capsys):
    """configs/thinfilm and luts/ are committed with the ownership marker, listing
    exactly the files git holds there, so a fresh clone's bake replaces them in place;
    a copy without the marker (or with a user's file in it) is refused."""
    import shutil

    for directory in (CONFIG_DIR, ROOT / "luts"):
        tracked = subprocess.run(
            ["git", "ls-files", "--", "."],
            cwd=directory,
            capture_output=True,
            text=True,
            check=True,
        ).stdout.split()
        if not tracked:
            pytest.skip("not a git checkout")
        assert set(tracked) - {io.MARKER} == marker_files(directory), directory
        assert io.MARKER in tracked
    cfg = tmp_path / "thinfilm"
    shutil.copytree(CONFIG_DIR, cfg)
    assert cli_run(["bake", "--out", str(cfg), "--quiet", "--clip-size", "9"], capsys)[0] == 0
    assert marker_files(cfg) == files_under(cfg)
    config_loads(cfg)
    shutil.rmtree(cfg)
    shutil.copytree(CONFIG_DIR, cfg, ignore=shutil.ignore_patterns(io.MARKER))
    code, _, err = cli_run(["bake", "--out", str(cfg), "--quiet"], capsys)
    one_line_error(code, err, "--out")
    shutil.rmtree(cfg)
    shutil.copytree(CONFIG_DIR, cfg)
    (cfg / "README.txt").write_text("mine")
    assert cli_run(["bake", "--out", str(cfg), "--quiet", "--clip-size", "9"], capsys)[0] == 0
    assert (cfg / "README.txt").read_text() == "mine"


def test_stale_temporaries_of_dead_processes_are_removed(tmp_path):
    dead = subprocess.Popen([sys.executable, "-c", "pass"])
    dead.wait()
    live = os.getppid()  # pytest's parent: alive for the whole test
    host = io_temporaries.self_id().split("-")[0]
    stale = tmp_path / f"{io.TMP_PREFIX}{host}-{dead.pid}-1-ab-x.clf"
    stale.write_text("half")
    keep = (
        tmp_path / f"{io.TMP_PREFIX}{io_temporaries.self_id().split('-')[0]}-{live}-"
        f"{io_temporaries.start_time(live)}-cd-y.clf"
    )
    keep.write_text("in use")
    foreign = tmp_path / f"{io.TMP_PREFIX}0badf00d-{dead.pid}-1-ef-z.clf"
    foreign.write_text("another host")  # another host's: kept until a day old
    with io.atomic_file(tmp_path / "out.txt") as tmp:
        tmp.write_text("new")
    assert not stale.exists() and keep.exists() and foreign.exists()
    os.utime(foreign, (time.time() - 2 * 86400,) * 2)
    io.clean_stale(tmp_path)
    assert not foreign.exists() and keep.exists()


# --------------------------------------------------------------------------- #
# Special files: written through, never replaced
# --------------------------------------------------------------------------- #
def device_node(tmp_path, name, minor):
    """A private character device node (1, minor) -- the null (3) or full (7) device --
    in ``tmp_path``. The tests never write to the real /dev: code that replaced a
    device node (run as root) would break the machine."""
    path = tmp_path / name
    try:
        os.mknod(path, stat.S_IFCHR | 0o666, os.makedev(1, minor))
        with open(path, "wb") as f:  # usable here (not a nodev mount)?
            f.write(b"")
    except OSError as error:
        if path.exists():
            path.unlink()
        pytest.skip(f"cannot make a device node here (needs CAP_MKNOD, not nodev): {error}")
    return path


def test_export_to_a_null_device_writes_through(tmp_path, capsys):
    null = device_node(tmp_path, "null", 3)
    before = os.stat(null)
    code, out, err = cli_run(
        ["export", "morpho", "--size", "8", "--format", "clf", "--out", str(null), "--quiet"],
        capsys,
    )
    assert code == 0, err
    after = os.stat(null)
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev
    assert after.st_ino == before.st_ino
    assert sorted(p.name for p in tmp_path.iterdir()) == ["null"]


def test_export_to_a_full_device_fails_in_one_line(tmp_path, capsys):
    full = device_node(tmp_path, "full", 7)
    before = os.stat(full)
    code, _, err = cli_run(
        ["export", "morpho", "--size", "8", "--format", "cube", "--out", str(full), "--quiet"],
        capsys,
    )
    one_line_error(code, err, str(full))
    after = os.stat(full)
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev
    assert after.st_ino == before.st_ino
    assert sorted(p.name for p in tmp_path.iterdir()) == ["full"]


def test_export_into_a_fifo_writes_through(tmp_path, capsys):
    fifo = tmp_path / "pipe.cube"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(fifo.read_bytes()), daemon=True)
    reader.start()
    code, _, err = cli_run(
        ["export", "morpho", "--size", "8", "--out", str(fifo), "--quiet"], capsys
    )
    reader.join(30)
    assert code == 0, err
    alive = reader.is_alive()
    if alive:  # the FIFO was replaced: unblock the reader with a writer of our own
        with open(fifo, "wb"):
            pass
    assert not alive and stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert got and b"\nLUT_1D_SIZE 8\n" in b"\n" + got[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["pipe.cube"]


def test_export_through_a_symlink_keeps_the_link(tmp_path, capsys):
    target = tmp_path / "real" / "lut.cube"
    target.parent.mkdir()
    target.write_text("old")
    link = tmp_path / "link.cube"
    link.symlink_to(target)
    code, _, err = cli_run(
        ["export", "morpho", "--size", "8", "--out", str(link), "--quiet"], capsys
    )
    assert code == 0, err
    assert link.is_symlink() and os.readlink(link) == str(target)
    assert "\nLUT_1D_SIZE 8\n" in "\n" + target.read_text()
    assert temporaries(tmp_path) == []


@pytest.mark.skipif(not Path("/proc/self/fd").is_dir(), reason="needs /proc/self/fd")
@pytest.mark.parametrize("via_link", [False, True])
def test_export_to_stdout_keeps_the_data_clean(tmp_path, via_link):
    """``--out`` naming standard output (``/proc/self/fd/1``, or a link to it as
    /dev/stdout is) writes the LUT there and the message to stderr. (Never /dev/stdout
    itself: code that replaced the link, run as root, would break the machine.)"""
    out = tmp_path / "captured.cube"
    target = "/proc/self/fd/1"
    if via_link:
        target = str(tmp_path / "stdout")
        os.symlink("/proc/self/fd/1", target)
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    with open(out, "wb") as f:
        p = subprocess.run(
            [
                sys.executable,
                "-m",
                "ocio_thinfilm",
                "export",
                "morpho",
                "--size",
                "8",
                "--format",
                "cube",
                "--out",
                target,
                "--quiet",
            ],
            stdout=f,
            stderr=subprocess.PIPE,
            text=True,
            env=env,
            timeout=120,
            cwd=tmp_path,
        )
    assert p.returncode == 0, p.stderr
    text = out.read_text()
    assert "\nLUT_1D_SIZE 8\n" in "\n" + text and "wrote" not in text
    assert f"wrote {target}" in p.stderr
    if via_link:
        assert os.readlink(target) == "/proc/self/fd/1"
    assert sorted(x.name for x in tmp_path.iterdir()) == sorted(
        ["captured.cube"] + (["stdout"] if via_link else [])
    )


def test_render_refuses_before_writing_when_an_output_is_a_directory(tmp_path, capsys):
    (tmp_path / "oil.exr").mkdir()
    code, _, err = cli_run(
        ["render", "oil", "--size", "16", "--out", str(tmp_path), "--quiet"], capsys
    )
    one_line_error(code, err, "oil.exr")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["oil.exr"]


# --------------------------------------------------------------------------- #
# Full disks
# --------------------------------------------------------------------------- #
@pytest.fixture
def small_disk(tmp_path):
    """A 1 MiB tmpfs (needs root with CAP_SYS_ADMIN; skips, saying so, otherwise)."""
    mnt = tmp_path / "small"
    mnt.mkdir()
    try:
        p = subprocess.run(
            ["mount", "-t", "tmpfs", "-o", "size=1m", "tmpfs", str(mnt)],
            capture_output=True,
            text=True,
            timeout=30,
        )
    except (OSError, subprocess.TimeoutExpired) as error:
        pytest.skip(f"cannot mount a tmpfs here: {error}")
    if p.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here (needs root and CAP_SYS_ADMIN): {p.stderr.strip()}")
    try:
        yield mnt
    finally:
        subprocess.run(["umount", "-l", str(mnt)], capture_output=True, timeout=30)


def fill(directory, leave=16384):
    """Fill the file system of ``directory``, leaving ``leave`` bytes free."""
    big = Path(directory) / "filler"
    fd = os.open(big, os.O_WRONLY | os.O_CREAT, 0o644)
    try:
        while os.write(fd, b"\0" * 65536) > 0:
            pass
    except OSError as error:
        assert error.errno == errno.ENOSPC
    finally:
        os.close(fd)
    # free exactly ``leave`` bytes again
    size = big.stat().st_size
    os.truncate(big, max(0, size - leave))


def test_full_disk_export_fails_and_keeps_the_old_file(small_disk, capsys):
    good = small_disk / "x.clf"
    assert (
        cli_run(["export", "morpho", "--size", "16", "--out", str(good), "--quiet"], capsys)[0] == 0
    )
    before = good.read_bytes()
    fill(small_disk)
    for fmt in ("clf", "cube"):
        target = small_disk / f"x.{fmt}"
        if fmt == "cube":
            target.write_bytes(b"LUT_1D_SIZE 2\n0 0 0\n1 1 1\n")
        old = target.read_bytes()
        code, _, err = cli_run(["export", "film", "--out", str(target), "--quiet"], capsys)
        one_line_error(code, err, str(target))
        assert target.read_bytes() == old
    assert good.read_bytes() == before
    assert temporaries(small_disk) == []


def test_full_disk_demo_and_render_keep_the_old_images(small_disk, capsys):
    png = small_disk / "strip.png"
    assert cli_run(["demo", "--out", str(png)], capsys)[0] == 0
    assert (
        cli_run(["render", "oil", "--size", "64", "--out", str(small_disk), "--quiet"], capsys)[0]
        == 0
    )
    before = snapshot(small_disk)
    fill(small_disk, leave=0)
    code, _, err = cli_run(["demo", "--out", str(png)], capsys)
    one_line_error(code, err, "strip.png")
    code, _, err = cli_run(
        ["render", "oil", "--size", "64", "--seed", "7", "--out", str(small_disk), "--quiet"],
        capsys,
    )
    one_line_error(code, err, str(small_disk))
    after = snapshot(small_disk)
    after.pop("filler"), before.pop("filler", None)
    assert after == before
    assert temporaries(small_disk) == []


def test_full_disk_bake_luts_leaves_out_as_it_was(small_disk, tmp_path, capsys):
    cfg = tmp_path / "cfg"
    assert cli_run(["bake", "--out", str(cfg), "--quiet", "--clip-size", "9"], capsys)[0] == 0
    before = snapshot(cfg)
    fill(small_disk)
    code, _, err = cli_run(
        [
            "bake",
            "--out",
            str(cfg),
            "--quiet",
            "--clip-size",
            "10",
            "--luts",
            str(small_disk / "luts"),
        ],
        capsys,
    )
    one_line_error(code, err)
    assert snapshot(cfg) == before
    assert not (small_disk / "luts").exists()
    assert temporaries(cfg, small_disk) == []
    # and a bake whose own directory is on the full disk: one line, nothing left
    code, _, err = cli_run(
        ["bake", "--out", str(small_disk / "cfg"), "--quiet", "--clip-size", "9"], capsys
    )
    one_line_error(code, err)
    assert "Traceback" not in err
    assert sorted(p.name for p in small_disk.iterdir()) == ["filler"]


def test_failing_fsync_keeps_the_old_files(tmp_path, capsys, monkeypatch):
    """Where no tmpfs can be mounted: the check before the rename fails (as a full
    disk's fsync or close would), and nothing is replaced."""
    good = tmp_path / "x.clf"
    png = tmp_path / "s.png"
    cfg = tmp_path / "cfg"
    assert (
        cli_run(["export", "morpho", "--size", "16", "--out", str(good), "--quiet"], capsys)[0] == 0
    )
    assert cli_run(["demo", "--out", str(png)], capsys)[0] == 0
    assert cli_run(["bake", "--out", str(cfg), "--quiet", "--clip-size", "9"], capsys)[0] == 0
    before = snapshot(tmp_path)

    def enospc(path):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))

    monkeypatch.setattr(durable, "fsync_file", enospc)
    for argv in (
        ["export", "film", "--out", str(good), "--quiet"],
        ["demo", "--out", str(png)],
        ["bake", "--out", str(cfg), "--quiet", "--clip-size", "10"],
    ):
        code, _, err = cli_run(argv, capsys)
        one_line_error(code, err, "No space left")
    assert snapshot(tmp_path) == before


# --------------------------------------------------------------------------- #
# Kills at every step of a bake's commit, and at random moments
# --------------------------------------------------------------------------- #
#: The commit's steps a bake is killed at: before it, after the marker, after the first
#: rename and the tenth (every rename takes the same path), after the renames, after the
#: commit.
KILL_POINTS = [
    "before-commit",
    "after-marker",
    "rename-0",
    "rename-9",
    "after-renames",
    "after-commit",
]


@pytest.fixture(scope="module")
def baked(tmp_path_factory):
    """A previous bake (clip size 5) to be replaced by one of clip size 6; ``.new``
    is the snapshot a complete clip size 6 bake leaves."""
    import shutil

    base = tmp_path_factory.mktemp("baked")
    assert cli.main(["bake", "--out", str(base / "cfg"), "--quiet", "--clip-size", "9"]) == 0
    assert cli.main(["bake", "--out", str(base / "new"), "--quiet", "--clip-size", "10"]) == 0

    def copy(dest):
        shutil.copytree(base / "cfg", dest, symlinks=True)

    copy.new = snapshot(base / "new")
    return copy


@pytest.mark.skipif(not hasattr(os, "fork"), reason="needs os.fork")
@pytest.mark.parametrize("point", KILL_POINTS)
def test_bake_killed_at_each_commit_step(tmp_path, baked, point):
    cfg = tmp_path / "cfg"
    baked(cfg)
    # the standalone set too (a second folder) where it changes what the kill leaves: in
    # the renames and after the commit (it costs 7 s a bake, so not at every point)
    argv = ["bake", "--out", str(cfg), "--quiet", "--clip-size", "10"]
    if point in ("rename-0", "after-commit"):
        argv += ["--luts", str(tmp_path / "luts")]
    pid = os.fork()
    if pid == 0:  # child: the bake, SIGKILLed by the hook at ``point``
        code = 99
        try:
            os.environ["OCIO_THINFILM_FAULT"] = point
            devnull = os.open(os.devnull, os.O_WRONLY)
            os.dup2(devnull, 1)
            os.dup2(devnull, 2)
            code = cli.main(argv)
        finally:
            os._exit(code)
    _, status = os.waitpid(pid, 0)
    assert os.WIFSIGNALED(status) and os.WTERMSIG(status) == signal.SIGKILL, status
    config_loads(cfg)  # old, new or a mix of complete files: it loads
    assert marker_files(cfg) >= files_under(cfg)  # everything of ours is listed
    # the next run cleans up and completes
    assert cli.main(argv) == 0
    config_loads(cfg)
    assert marker_files(cfg) == files_under(cfg)
    assert temporaries(tmp_path) == []


def _wait_for_handlers(pid, timeout=20.0):
    """Until the child has installed its SIGTERM handler (``SigCgt`` in /proc):
    from then on a signal reaches ocio-thinfilm's code, not the interpreter's start-up."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        try:
            for line in Path(f"/proc/{pid}/status").read_text().splitlines():
                if line.startswith("SigCgt:") and int(line.split()[1], 16) & (
                    1 << (signal.SIGTERM - 1)
                ):
                    return True
        except (OSError, ValueError):
            return False
        time.sleep(0.002)
    return False


def _default_signals():
    """In the child: default SIGINT and SIGTERM handling, as a shell gives a foreground job.

    A suite started in the background (``nohup``, ``&``) inherits SIGINT ignored, and an
    ignored signal stays ignored in children; the tests send signals the way a user at a
    terminal does.
    """
    signal.signal(signal.SIGINT, signal.SIG_DFL)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


def _bake_process(out, *extra):
    env = dict(os.environ, PYTHONPATH=str(ROOT) + os.pathsep + os.environ.get("PYTHONPATH", ""))
    env.pop("OCIO_THINFILM_FAULT", None)
    return subprocess.Popen(
        [
            sys.executable,
            "-m",
            "ocio_thinfilm",
            "bake",
            "--out",
            str(out),
            "--quiet",
            "--clip-size",
            "10",
            *extra,
        ],
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        preexec_fn=_default_signals,
    )


needs_proc = pytest.mark.skipif(
    not Path("/proc/self/status").exists(),
    reason="needs /proc to see when the handlers are in place",
)


@needs_proc
def test_bake_killed_at_random_moments(tmp_path, baked):
    rng = random.Random(9)
    cfg = tmp_path / "cfg"
    baked(cfg)
    for delay in sorted(rng.uniform(0.0, 0.8) for _ in range(4)):
        p = _bake_process(cfg)
        assert _wait_for_handlers(p.pid)
        time.sleep(delay)
        p.kill()
        p.communicate(timeout=60)
        config_loads(cfg)
    assert cli.main(["bake", "--out", str(cfg), "--quiet", "--clip-size", "9"]) == 0
    config_loads(cfg)
    assert temporaries(tmp_path) == []


@needs_proc
@pytest.mark.parametrize("signum,code", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_signal_gives_one_line_and_128_plus_n(tmp_path, baked, signum, code):
    rng = random.Random(int(signum))
    cfg = tmp_path / "cfg"
    baked(cfg)
    outcomes = set()
    for delay in [0.0] + [rng.uniform(0.0, 0.6) for _ in range(2)]:
        before = snapshot(cfg)
        p = _bake_process(cfg, "--luts", str(tmp_path / "luts"))
        assert _wait_for_handlers(p.pid)
        time.sleep(delay)
        p.send_signal(signum)
        out, err = p.communicate(timeout=60)
        lines = [line for line in err.splitlines() if line.strip()]
        if p.returncode == 0:  # finished before the signal was sent
            outcomes.add("done")
            assert lines == [] and "wrote" in out
        else:
            outcomes.add("interrupted")
            assert p.returncode == code, (p.returncode, err)
            assert len(lines) == 1 and lines[0].startswith("ocio-thinfilm"), err
            assert "interrupted" in lines[0]
            # before the commit: nothing changed; during it: the commit completes
            assert snapshot(cfg) in (before, baked.new)
        assert temporaries(tmp_path) == []
        config_loads(cfg)
    assert "interrupted" in outcomes  # delay 0: always before the work is done


# --------------------------------------------------------------------------- #
# One-line errors naming the option
# --------------------------------------------------------------------------- #
@pytest.mark.parametrize(
    "argv,needles",
    [
        (["demo", "--thickness", "abc"], ["ocio-thinfilm demo:", "--thickness", "number"]),
        (["export", "film", "--range", "0"], ["ocio-thinfilm export film:", "--range", "MIN MAX"]),
        (["export"], ["ocio-thinfilm export:", "TABLE", "film"]),
        (
            ["export", "film", "--no-such-option"],
            ["ocio-thinfilm export film:", "--no-such-option"],
        ),
        (["export", "nothing"], ["ocio-thinfilm export:", "nothing", "film, morpho, clip"]),
        (["bake", "--frobnicate"], ["ocio-thinfilm bake:", "--frobnicate"]),
        (["nosuch"], ["ocio-thinfilm:", "nosuch", "bake"]),
        ([], ["ocio-thinfilm:", "no command", "export"]),
        (["render", "oil", "--size", "5x5"], ["ocio-thinfilm render:", "--size"]),
    ],
)
def test_argument_errors_are_one_line(argv, needles, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    code, out, err = cli_run(argv, capsys)
    one_line_error(code, err, *needles)
    assert "usage:" not in err and out == ""
    assert list(tmp_path.iterdir()) == []


def test_bake_luts_nested_in_out_is_refused(tmp_path, capsys):
    for luts in ("cfg/luts", "cfg", "."):
        code, _, err = cli_run(
            [
                "bake",
                "--out",
                str(tmp_path / "cfg"),
                "--luts",
                str(tmp_path / luts),
                "--quiet",
                "--clip-size",
                "9",
            ],
            capsys,
        )
        one_line_error(code, err, "--luts")
    assert list(tmp_path.iterdir()) == []


def test_a_failed_write_leaves_no_new_directories(tmp_path, capsys, monkeypatch):
    def enospc(path):
        raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC), str(path))

    monkeypatch.setattr(durable, "fsync_file", enospc)
    code, _, err = cli_run(
        ["export", "morpho", "--size", "8", "--out", str(tmp_path / "x.cube"), "--quiet"],
        capsys,
    )
    one_line_error(code, err, "x.cube")
    code, _, err = cli_run(
        ["bake", "--out", str(tmp_path / "cfg"), "--quiet", "--clip-size", "9"], capsys
    )
    one_line_error(code, err)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "command",
    [
        ["export", "view", "--from", "ACEScct", "--display", "sRGB"]
        + ["--view", "Channel Clamp", "--format", "cube", "--out", "{tmp}/c.spi1d"],
        ["export", "film", "--format", "cube", "--out", "{tmp}/f.spi1d"],
        ["export", "morpho", "--format", "clf", "--out", "{tmp}/m.csp"],
    ],
)
def test_a_format_that_contradicts_the_file_name_is_refused(tmp_path, capsys, command):
    """--format cube with --out c.spi1d would write a .cube under a .spi1d name, which
    every host reading by extension misreads: one line naming --format, nothing written."""
    args = [a.replace("{tmp}", str(tmp_path)) for a in command]
    code, _, err = cli_run(args, capsys)
    one_line_error(code, err, "--format", "ends in .")
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "command",
    [
        ["export", "morpho", "--size", "8", "--out", "{tmp}/missing/x.cube"],
        ["export", "film", "--size", "16", "--out", "{tmp}/missing/dir/soap.cube"],
        ["export", "film", "--films", "docs/films.toml", "--film", "Temper"]
        + ["--out", "{tmp}/missing/dir/temper.cube"],
        ["export", "film", "--films", "docs/films.toml", "--film", "Temper"]
        + ["--out", "{tmp}/missing/dir"],
        ["export", "film", "--films", "docs/films.toml", "--film", "Temper"]
        + ["--swatches", "{tmp}/missing/sheet.csv"],
        ["bake", "--clip-size", "9", "--out", "{tmp}/missing/cfg"],
        ["render", "oil", "--size", "16", "--out", "{tmp}/missing/deeper"],
    ],
)
def test_outputs_never_create_missing_folders_above_them(tmp_path, capsys, command):
    """One rule for every command: the tool creates its output (a file, or an output
    folder), never the missing folders above it, so a mistyped path is caught: one
    line naming the missing folder, exit 2, nothing created."""
    args = [a.replace("{tmp}", str(tmp_path)) for a in command]
    code, _, err = cli_run([*args, "--quiet"], capsys)
    one_line_error(code, err, "does not exist")
    assert list(tmp_path.iterdir()) == []


def test_progress_in_a_log_is_plain_lines_after_a_few_seconds(capsys):
    """Where stderr is not a terminal (a log, CI), a long bake or export prints plain
    progress lines: none in the first seconds (quick runs stay silent), then one line per
    interval naming the stage, and a last line; no carriage returns."""
    from ocio_thinfilm.export.files import LogProgress, progress_bar

    assert isinstance(progress_bar(True, 3, "bake x"), LogProgress)  # capsys: not a tty
    assert progress_bar(False, 3, "bake x") is None  # --quiet
    now = [0.0]
    bar = LogProgress(10, "bake cfg", clock=lambda: now[0])
    for t, stage in (
        (1.0, "a.clf"),
        (2.0, "b.clf"),
        (6.0, "c.clf"),
        (8.0, "d.clf"),
        (22.0, "e.clf"),
    ):
        now[0] = t
        bar.set_postfix_str(stage)
        bar.update(1)
    bar.close()
    lines = capsys.readouterr().err.splitlines()
    assert lines == [
        "bake cfg: 3/10 c.clf (6 s)",
        "bake cfg: 5/10 e.clf (22 s)",
        "bake cfg: 5/10 e.clf (22 s), done",
    ]
    quick = LogProgress(10, "bake cfg", clock=lambda: 1.0)
    quick.update(10)
    quick.close()
    assert capsys.readouterr().err == ""
