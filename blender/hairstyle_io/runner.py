# Running a chain of the pipeline's stages in the background, one subprocess after the
# other, without Blender: the stages write into a temporary work folder inside the output
# folder; only when the last one succeeds are its files moved into the output folder
# (each by a rename). A failure or a Cancel kills the running stage, removes the work
# folder with everything in it (the stages' own temporary files too) and the output
# folder if the chain made it, so nothing half-written is left and the files there before
# are untouched. A failure's message is the stage's one-line error (its last stderr line).
#
#   chain = Chain(steps, folder, keep=["styles.h5"])
#   chain.start(prepare=write_inputs)      # prepare(work_folder) before the first stage
#   while chain.poll() == RUNNING: ...     # or chain.cancel()

import atexit
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

RUNNING, DONE, FAILED, CANCELLED = "running", "done", "failed", "cancelled"
WORK_PREFIX = ".hairstyle-work-"
# Seconds a stage is given to end after SIGTERM before it is killed.
TERMINATE_WAIT_S = 2.0

_chains = set()  # the chains running in this process, ended when it exits

# A stage runs in a process group of its own (Python 3.11's process_group; before it, a
# setpgid in the child).
_OWN_PROCESS_GROUP = ({"process_group": 0} if sys.version_info >= (3, 11)
                      else {"preexec_fn": os.setpgrp})


class Step:
    """One stage of a chain: its command line (run in the work folder, where relative
    paths point) and the seconds it is expected to take (its share of the progress)."""

    def __init__(self, name, command, expected_s=1.0):
        self.name = name
        self.command = [str(part) for part in command]
        self.expected_s = float(expected_s)


def error_line(stage, stderr_text, returncode):
    """One line saying why `stage` failed: its own error line (the last line with
    ': error:'; else its last line), or its exit status or signal."""
    lines = [line.strip() for line in stderr_text.splitlines() if line.strip()]
    errors = [line for line in lines if ": error:" in line]
    if errors:
        return errors[-1]
    if returncode < 0:
        try:
            name = signal.Signals(-returncode).name
        except ValueError:
            name = str(-returncode)
        return f"{stage} was ended by signal {name}"
    if lines:
        return f"{stage}: {lines[-1]}" if not lines[-1].startswith(stage) else lines[-1]
    return f"{stage} failed with exit status {returncode}"


class Chain:
    """Steps run one after the other in a work folder inside `folder`; on success the
    names in `keep` (files or folders in the work folder) replace those in `folder`, and
    the names in `remove` are deleted from it (results the new ones make stale)."""

    def __init__(self, steps, folder, keep, remove=(), environment=None):
        self.steps = list(steps)
        self.folder = os.path.abspath(folder)
        self.keep = list(keep)
        self.remove = list(remove)
        self.environment = environment
        self.work = None
        self.state = None
        self.error = ""
        self.index = -1  # the running step
        self._made_folder = None  # the outermost folder start() made
        self._process = None
        self._stderr = None
        self._step_started = 0.0
        self._done_s = 0.0

    # -- what a panel shows --------------------------------------------------------
    @property
    def stage(self):
        """The running stage's name ('' before and after)."""
        return self.steps[self.index].name if 0 <= self.index < len(self.steps) else ""

    @property
    def progress(self):
        """0 to 1: the finished stages' expected time, and the running one's so far (held
        under its expected time), of the whole chain's."""
        total = sum(step.expected_s for step in self.steps) or 1.0
        if self.state == DONE:
            return 1.0
        running = 0.0
        if self._process is not None:
            expected = self.steps[self.index].expected_s
            running = min(time.monotonic() - self._step_started, 0.95 * expected)
        return min((self._done_s + running) / total, 1.0)

    def describe(self):
        if self.state == RUNNING and self.stage:
            return f"{self.stage} ({self.index + 1} of {len(self.steps)})"
        return self.state or ""

    # -- running ---------------------------------------------------------------------
    def start(self, prepare=None):
        """Makes the work folder, runs prepare(work) (an exception there removes it and
        is raised again) and starts the first stage."""
        if not os.path.isdir(self.folder):
            self._made_folder = _first_missing(self.folder)
            os.makedirs(self.folder)
        self.work = tempfile.mkdtemp(prefix=WORK_PREFIX, dir=self.folder)
        self.state = RUNNING
        _chains.add(self)
        try:
            if prepare is not None:
                prepare(self.work)
            self._start_next()
        except BaseException:
            self._clean_up()
            self.state = FAILED
            raise
        return self

    def _start_next(self):
        self.index += 1
        if self.index >= len(self.steps):
            self._commit()
            return
        step = self.steps[self.index]
        self._stderr = open(os.path.join(self.work, f".{step.name}.stderr"), "w+b")
        self._step_started = time.monotonic()
        try:
            self._process = subprocess.Popen(
                step.command, cwd=self.work, stdin=subprocess.DEVNULL,
                stdout=subprocess.DEVNULL, stderr=self._stderr, env=self.environment,
                **_OWN_PROCESS_GROUP)  # a Cancel ends all of it
        except OSError as error:
            self._process = None
            self._fail(f"{step.name}: cannot run {step.command[0]}: {error.strerror}")

    def poll(self):
        """Advances the chain (starts the next stage when one has ended) and returns its
        state: RUNNING, DONE, FAILED or CANCELLED."""
        if self.state != RUNNING or self._process is None:
            return self.state
        returncode = self._process.poll()
        if returncode is None:
            return RUNNING
        step = self.steps[self.index]
        self._process = None
        self._stderr.seek(0)
        stderr_text = self._stderr.read().decode(errors="replace")
        self._stderr.close()
        if returncode != 0:
            self._fail(error_line(step.name, stderr_text, returncode))
            return self.state
        self._done_s += step.expected_s
        try:
            self._start_next()
        except OSError as error:
            self._fail(f"hairstyle: cannot move the results into {self.folder}: {error}")
        return self.state

    def wait(self, interval_s=0.05, on_progress=None):
        """Polls until the chain ends, calling on_progress(chain) after each poll;
        returns the final state."""
        while self.poll() == RUNNING:
            if on_progress is not None:
                on_progress(self)
            if self.state == RUNNING:
                time.sleep(interval_s)
        return self.state

    def cancel(self):
        """Ends the running stage (SIGTERM, then SIGKILL), removes the work folder and what
        the chain made; the output folder keeps what it had."""
        if self.state != RUNNING:
            return
        self._end_process()
        self._clean_up()
        self.state = CANCELLED

    # -- ending ----------------------------------------------------------------------
    def _end_process(self):
        process, self._process = self._process, None
        if process is None:
            return
        for sig, wait_s in ((signal.SIGTERM, TERMINATE_WAIT_S), (signal.SIGKILL, None)):
            try:
                os.killpg(process.pid, sig)
            except ProcessLookupError:
                break
            try:
                process.wait(timeout=wait_s)
                break
            except subprocess.TimeoutExpired:
                continue

    def _fail(self, message):
        self._end_process()
        self._clean_up()
        self.error = message
        self.state = FAILED

    def _clean_up(self):
        _chains.discard(self)
        if self._stderr is not None and not self._stderr.closed:
            self._stderr.close()
        if self.work:
            shutil.rmtree(self.work, ignore_errors=True)
        if self._made_folder:
            folder = self.folder
            while True:  # the folders start() made, where they are empty
                try:
                    os.rmdir(folder)
                except OSError:
                    break
                if folder == self._made_folder:
                    break
                folder = os.path.dirname(folder)

    def _commit(self):
        for name in self.remove:
            _remove(os.path.join(self.folder, name))
        for name in self.keep:
            source, target = os.path.join(self.work, name), os.path.join(self.folder, name)
            if os.path.isdir(source):
                _remove(target)
            os.replace(source, target)
        shutil.rmtree(self.work, ignore_errors=True)
        _chains.discard(self)
        self.index = len(self.steps)
        self.state = DONE


def _first_missing(folder):
    """The outermost folder of `folder`'s path that does not exist."""
    missing = folder
    while not os.path.exists(os.path.dirname(missing)):
        missing = os.path.dirname(missing)
    return missing


def _remove(path):
    if os.path.isdir(path) and not os.path.islink(path):
        shutil.rmtree(path)
    elif os.path.lexists(path):
        os.remove(path)


def cancel_all():
    """Cancels every chain still running (Blender quitting, another file opened)."""
    for chain in list(_chains):
        chain.cancel()


atexit.register(cancel_all)
