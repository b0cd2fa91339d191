#!/usr/bin/python3
"""A private virtual X display (Xvfb) for Debian's VTK and ParaView, which render through X only.

`xvfb-run -a` picks a display number by looking for lock files and only then starts Xvfb, so two
started at once (or one next to a server still shutting down) can pick the same number; the
loser runs its client against a server that refuses it ("bad X server connection") and carries
on. Here Xvfb picks the number itself (-displayfd: it tries :0, :1, ... and keeps the first
whose socket it can bind, the bind being what is atomic) and writes it back once it accepts
connections, so the display handed out is the server's own and ready. Such a server writes no
/tmp/.XN-lock, so an `Xvfb :N` started by hand meanwhile may find :N taken.
The server dies with the process that started it (PR_SET_PDEATHSIG), even one killed with -9.
It runs with -noreset: an X server resets when its last client leaves, and drops a client that
connects meanwhile; pvbatch connects and leaves several times before it opens its window, so
without it one start in ten to forty (more on a busy machine) ended in "bad X server connection".

    with virtual_display() as display:
        subprocess.run(command, env={**os.environ, "DISPLAY": display})

or from a shell:  scripts/virtual_display.py COMMAND [ARGS...]  (exits with COMMAND's code,
128 + N if a signal N ended it, 127 if there is no COMMAND, 1 if Xvfb did not start)
"""
import contextlib
import ctypes
import os
import selectors
import shutil
import signal
import subprocess
import sys
import tempfile

SCREEN = "1920x1200x24"   # width x height x depth; larger images render offscreen anyway
START_TIMEOUT_S = 30


class DisplayError(RuntimeError):
    """Xvfb is not installed or did not start; the message says which, with Xvfb's own output."""


PR_SET_PDEATHSIG = 1  # linux/prctl.h


def die_with_parent():
    """In the child before exec: SIGTERM when the process that started it ends."""
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


@contextlib.contextmanager
def virtual_display():
    """Start Xvfb on a free display, yield its name (':N'), and stop it on leaving."""
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        raise DisplayError("no Xvfb: install the Debian package xvfb (scripts/install-deps.sh)")
    with tempfile.TemporaryFile("w+") as log:
        read_end, write_end = os.pipe()
        try:
            server = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", SCREEN,
                                       "-nolisten", "tcp", "-noreset"], pass_fds=(write_end,), preexec_fn=die_with_parent,
                                      stdin=subprocess.DEVNULL, stdout=log, stderr=log)
        except OSError as error:
            os.close(read_end)
            raise DisplayError(f"cannot start {xvfb}: {error}") from error
        finally:
            os.close(write_end)
        try:
            number = read_display_number(read_end)
            if not number:
                if server.poll() is None:
                    server.kill()
                    what = f"gave no display within {START_TIMEOUT_S} s"
                else:
                    what = f"exited with {server.returncode} before opening a display"
                server.wait()
                log.seek(0)
                raise DisplayError(f"Xvfb {what}:\n{log.read()}")
            yield f":{number}"
        finally:
            if server.poll() is None:
                server.terminate()
                try:
                    server.wait(timeout=START_TIMEOUT_S)
                except subprocess.TimeoutExpired:
                    server.kill()
                    server.wait()


def read_display_number(read_end):
    """The display number Xvfb writes to the pipe when it is ready ('' if the pipe closes first,
    Xvfb having exited, or nothing comes within START_TIMEOUT_S)."""
    with os.fdopen(read_end) as pipe, selectors.DefaultSelector() as selector:
        selector.register(pipe, selectors.EVENT_READ)
        return pipe.readline().strip() if selector.select(timeout=START_TIMEOUT_S) else ""


def stop_on_sigterm(signum, frame):
    raise SystemExit(128 + signum)  # through the with block, so the server is stopped


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    signal.signal(signal.SIGTERM, stop_on_sigterm)
    try:
        with virtual_display() as display:
            code = subprocess.call(sys.argv[1:], env={**os.environ, "DISPLAY": display})
            return 128 - code if code < 0 else code
    except DisplayError as error:
        sys.exit(f"virtual_display: {error}")
    except FileNotFoundError as error:
        print(f"virtual_display: {error}", file=sys.stderr)
        return 127


if __name__ == "__main__":
    sys.exit(main())
