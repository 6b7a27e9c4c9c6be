# Drives a headless LinuxCNC (the tests' controller): machine on, homed, then runs a program
# in automatic mode as an operator would press Cycle Start, optionally aborting it after some
# seconds. Exit 0 when the program ran as asked.
#   drive.py wait                      until the controller answers (at most 60 s)
#   drive.py run PROGRAM [--abort-after S] [--feed-scale F]
import sys
import time

import linuxcnc

c = None
s = None


def until(check, seconds, what):
    deadline = time.time() + seconds
    while time.time() < deadline:
        s.poll()
        if check():
            return
        time.sleep(0.02)
    sys.exit("drive.py: timed out waiting for " + what)


def ready():
    c.state(linuxcnc.STATE_ESTOP_RESET)
    c.wait_complete()
    c.state(linuxcnc.STATE_ON)
    c.wait_complete()
    until(lambda: s.task_state == linuxcnc.STATE_ON, 10, "machine on")
    s.poll()
    if not all(s.homed[:3]):
        c.mode(linuxcnc.MODE_MANUAL)
        c.wait_complete()
        c.home(-1)
        until(lambda: all(s.homed[:3]), 60, "homing")
    c.mode(linuxcnc.MODE_AUTO)
    c.wait_complete()


def run(program, abort_after, feed_scale):
    ready()
    c.program_open(program)
    c.wait_complete()
    c.feedrate(feed_scale)
    c.auto(linuxcnc.AUTO_RUN, 0)
    started = time.time()
    until(lambda: s.interp_state != linuxcnc.INTERP_IDLE, 10, "the run to start")
    while True:
        s.poll()
        if s.interp_state == linuxcnc.INTERP_IDLE:
            return
        if abort_after is not None and time.time() - started > abort_after:
            c.abort()
            c.wait_complete()
            until(lambda: s.interp_state == linuxcnc.INTERP_IDLE, 10, "the abort")
            return
        if time.time() - started > 240:
            sys.exit("drive.py: the program did not end in 240 s")
        time.sleep(0.02)


if sys.argv[1] == "wait":
    deadline = time.time() + 60
    while True:
        try:  # a status channel made before the controller was up never connects: a new one each time
            linuxcnc.stat().poll()
            break
        except (linuxcnc.error, SystemError):  # no controller yet, or one still starting
            if time.time() > deadline:
                sys.exit("drive.py: no controller after 60 s")
            time.sleep(0.5)
else:
    c = linuxcnc.command()
    s = linuxcnc.stat()
    args = sys.argv[2:]
    program = args[0]
    abort_after = float(args[args.index("--abort-after") + 1]) if "--abort-after" in args else None
    feed_scale = float(args[args.index("--feed-scale") + 1]) if "--feed-scale" in args else 1.0
    run(program, abort_after, feed_scale)
