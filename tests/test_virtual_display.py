#!/usr/bin/python3
"""scripts/virtual_display.py: clients started together each get a display of their own, ready
when they start, and the server is gone when they end.

Starts CLIENTS at once. Each connects to the X socket of its DISPLAY (refused if the server is not
listening yet), marks itself in a shared folder, waits until all have (so all displays are held
at the same time and no number can be reused), and prints its display and the process id of the
server that accepted it (SO_PEERCRED). Each must exit 0, the names must all differ (xvfb-run -a
can hand two the same one), and after all have ended none of those servers may still run. The
check names the servers, not the sockets: a display number freed by one client can be taken at
once by the Xvfb of a test running beside this one (the paraview case), whose socket is then
rightly there. Prints `virtual_display METRIC VALUE TOLERANCE PASS|FAIL`; exits 1 if a check
fails.
"""
import subprocess
import sys
import tempfile
from pathlib import Path

REPO = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(REPO / "verification"))
import ydry_case  # noqa: E402

CLIENTS = 6
BARRIER_TIMEOUT_S = 60
CLIENT = f"""
import os, socket, struct, sys, time
from pathlib import Path
display, here = os.environ["DISPLAY"], Path(sys.argv[1])
s = socket.socket(socket.AF_UNIX)
s.connect("/tmp/.X11-unix/X" + display[1:])
(here / str(os.getpid())).touch()
deadline = time.monotonic() + {BARRIER_TIMEOUT_S}
while len(list(here.iterdir())) < {CLIENTS}:
    if time.monotonic() > deadline:
        sys.exit("the other clients never connected")
    time.sleep(0.05)
server_pid = struct.unpack("3i", s.getsockopt(socket.SOL_SOCKET, socket.SO_PEERCRED, 12))[0]
print(display, server_pid)
"""


def server_runs(pid):
    """Whether process PID is still an Xvfb (a new process reusing the number is not)."""
    try:
        return Path(f"/proc/{pid}/comm").read_text().strip() == "Xvfb"
    except OSError:
        return False


def main():
    verdicts = ydry_case.Verdicts("virtual_display")
    with tempfile.TemporaryDirectory(prefix="ydry_displays_") as barrier:
        runs = [subprocess.Popen([sys.executable, str(REPO / "scripts" / "virtual_display.py"),
                                  sys.executable, "-c", CLIENT, barrier], stdout=subprocess.PIPE,
                                 stderr=subprocess.STDOUT, text=True) for _ in range(CLIENTS)]
        outputs = [run.communicate(timeout=120)[0] for run in runs]
    failed = [out for run, out in zip(runs, outputs) if run.returncode != 0]
    for out in failed:
        print(f"info: a client failed:\n{out}")
    verdicts.check("clients_exit_0", CLIENTS - len(failed), CLIENTS, not failed)
    answers = [out.split() for out in outputs if len(out.split()) == 2]
    displays = {display for display, _ in answers}
    print(f"info: displays {sorted(displays)}")
    verdicts.check("distinct_displays", len(displays), CLIENTS, len(displays) == CLIENTS)
    left = [pid for _, pid in answers if server_runs(pid)]
    verdicts.check("servers_left", len(left), 0, not left)
    return verdicts.exit_code()


if __name__ == "__main__":
    sys.exit(main())
