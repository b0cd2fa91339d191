#!/usr/bin/python3
"""A private virtual X display (Xvfb) for Debian's VTK and ParaView, which render through X only.

`xvfb-run -a` picks a display number by looking for lock files and only then starts Xvfb, so two
started at once (or one next to a server still shutting down) can pick the same number; the
loser runs its client against a server that refuses it ("bad X server connection") and carries
on. Here Xvfb picks the number itself (-displayfd: it tries :0, :1, ... taking each lock
atomically) and writes it back once it accepts connections, so the display handed out is the
server's own and ready.

    with virtual_display() as display:
        subprocess.run(command, env={**os.environ, "DISPLAY": display})

or from a shell:  scripts/virtual_display.py COMMAND [ARGS...]  (exits with COMMAND's code)
"""
import contextlib
import os
import selectors
import shutil
import subprocess
import sys
import tempfile

SCREEN = "1920x1200x24"   # width x height x depth; larger images render offscreen anyway
START_TIMEOUT_S = 30


class DisplayError(RuntimeError):
    """Xvfb is not installed or did not start; the message says which, with Xvfb's own output."""


@contextlib.contextmanager
def virtual_display():
    """Start Xvfb on a free display, yield its name (':N'), and stop it on leaving."""
    xvfb = shutil.which("Xvfb")
    if xvfb is None:
        raise DisplayError("no Xvfb: install the Debian package xvfb (scripts/install-deps.sh)")
    read_end, write_end = os.pipe()
    with tempfile.TemporaryFile("w+") as log:
        server = subprocess.Popen([xvfb, "-displayfd", str(write_end), "-screen", "0", SCREEN,
                                   "-nolisten", "tcp"], pass_fds=(write_end,),
                                  stdin=subprocess.DEVNULL, stdout=log, stderr=log)
        os.close(write_end)
        try:
            number = read_display_number(read_end, server)
            if not number:
                log.seek(0)
                raise DisplayError(f"Xvfb exited with {server.poll()} before opening a display:\n"
                                   f"{log.read()}")
            yield f":{number}"
        finally:
            server.terminate()
            try:
                server.wait(timeout=START_TIMEOUT_S)
            except subprocess.TimeoutExpired:
                server.kill()
                server.wait()


def read_display_number(read_end, server):
    """The display number Xvfb writes to the pipe when it is ready ('' if it exits first or
    says nothing within START_TIMEOUT_S)."""
    with os.fdopen(read_end) as pipe, selectors.DefaultSelector() as selector:
        selector.register(pipe, selectors.EVENT_READ)
        if not selector.select(timeout=START_TIMEOUT_S):
            server.kill()
            return ""
        return pipe.readline().strip()


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    try:
        with virtual_display() as display:
            return subprocess.call(sys.argv[1:], env={**os.environ, "DISPLAY": display})
    except DisplayError as error:
        sys.exit(f"virtual_display: {error}")


if __name__ == "__main__":
    sys.exit(main())
