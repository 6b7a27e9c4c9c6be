# The LinuxCNC side of `ncbridge capture linuxcnc`: reads the controller's status through
# LinuxCNC's own Python module (the status buffer the GUIs read: no NML commands are sent, the
# controller is never slowed) every POLL seconds and writes one JSON line to standard output
# whenever something a capture needs changes. Runs as the controller's user, beside it.
# Lines: {"kind": "sample", ...}, {"kind": "tools", ...}, {"kind": "lost", "reason": ...}.
import json
import sys
import time

POLL = float(sys.argv[1]) if len(sys.argv) > 1 else 0.005


def emit(record):
    sys.stdout.write(json.dumps(record, separators=(",", ":")) + "\n")
    sys.stdout.flush()


try:
    import linuxcnc
except ImportError as e:
    emit({"kind": "fatal", "reason": "the LinuxCNC Python module is not installed (%s)" % e})
    sys.exit(2)

MODES = {linuxcnc.MODE_AUTO: "auto", linuxcnc.MODE_MDI: "mdi", linuxcnc.MODE_MANUAL: "manual"}


def tool_table(stat):
    # The loaded tool table as LinuxCNC .tbl lines, in the machine's linear units.
    lines = []
    for index, t in enumerate(stat.tool_table):
        if index == 0 or t.id <= 0:  # entry 0 is the tool in the spindle, listed again below
            continue
        lines.append("T%d P%d Z%.6f D%.6f" % (t.id, t.id, t.zoffset, t.diameter))
    return "\n".join(lines) + ("\n" if lines else "")


def watch():
    stat = linuxcnc.stat()
    errors = linuxcnc.error_channel()
    stat.poll()  # raises linuxcnc.error when no controller runs
    inch = abs(stat.linear_units - 1.0 / 25.4) < 1e-6
    last_tools = None
    last = None
    running = False
    pending_fault = ""
    while True:
        stat.poll()
        tools = tool_table(stat)
        if tools != last_tools:
            emit({"kind": "tools", "table": tools, "inch": inch})
            last_tools = tools
        error = errors.poll()
        if error and error[0] in (linuxcnc.OPERATOR_ERROR, linuxcnc.NML_ERROR) and running:
            pending_fault = error[1]
        interp = stat.interp_state
        if interp == linuxcnc.INTERP_IDLE:
            state = "idle"
        elif interp == linuxcnc.INTERP_PAUSED or stat.task_paused:
            state = "paused"
        else:
            state = "running"
        fault = ""
        if stat.task_state != linuxcnc.STATE_ON and running:
            fault = "the machine was switched off or e-stopped"
        elif pending_fault:
            fault = pending_fault
        elif state == "idle" and running and stat.motion_line == 0:
            # LinuxCNC keeps the last line after a program ends and clears it on an abort
            fault = "the run was aborted"
        record = {
            "kind": "sample",
            "mode": MODES.get(stat.task_mode, "manual"),
            "interp": state,
            "program": stat.file,
            "line": stat.motion_line if state != "idle" or not fault else 0,
            "fault": fault,
        }
        if record != last:
            emit(record)
            last = record
        if state != "idle" and stat.task_mode == linuxcnc.MODE_AUTO:
            running = True
        elif state == "idle":
            running = False
            pending_fault = ""
        time.sleep(POLL)


while True:
    try:
        watch()
    except (linuxcnc.error, SystemError) as e:  # none running, or one starting or stopping
        emit({"kind": "lost", "reason": "no LinuxCNC controller: %s" % e})
        time.sleep(1.0)
    except BrokenPipeError:
        sys.exit(0)
