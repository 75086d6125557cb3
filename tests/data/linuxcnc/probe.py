#!/usr/bin/python3
"""The display program of the test machine (machine.ini, [DISPLAY] DISPLAY): no display,
it drives LinuxCNC through its Python interface and reads the HAL pins.

It reads probes.json (a list of probes, each a list of MDI commands, the last of which
ends at the probed position), runs each probe's commands, waits until the joints stand
and the compensation filter has reached its value, and writes results.json: per probe and
joint, the HAL pins pos-cmd, motor-pos-cmd and motor-offset, read with hal.get_value
(doubles, printed by json with every digit; halcmd prints about 7 significant digits),
and the messages of LinuxCNC's error channel. When it exits, LinuxCNC shuts down.
"""
import json
import sys
import time
import traceback

import hal
import linuxcnc

JOINTS = 4
PINS = ("pos-cmd", "motor-pos-cmd", "motor-offset", "backlash-corr", "backlash-filt")
SETTLE_S = 0.05

stat = linuxcnc.stat()
command = linuxcnc.command()
errors = linuxcnc.error_channel()
messages = []


def drain_errors():
    while True:
        e = errors.poll()
        if not e:
            return
        messages.append(e[1])


def wait_for(done, what, seconds=20.0):
    end = time.time() + seconds
    while time.time() < end:
        stat.poll()
        drain_errors()
        if done():
            return
        time.sleep(0.01)
    raise RuntimeError("timed out waiting for %s; joints: %r" % (what, joints()))


def joints():
    """Each joint's pins, and the ramp's speed."""
    return [{p: pin(j, p) for p in PINS + ("vel-cmd", "backlash-vel")} for j in range(JOINTS)]


def pin(joint, name):
    return hal.get_value("joint.%d.%s" % (joint, name))


def settled():
    """Every joint stands still and its compensation ramp has stopped: at its target, or
    short of it where LinuxCNC's ramp stalls with a speed of about 1e-17 (the test judges
    the difference)."""
    return all(
        pin(j, "vel-cmd") == 0.0 and abs(pin(j, "backlash-vel")) < 1e-9 for j in range(JOINTS)
    )


def probe(commands):
    for line in commands:
        command.mdi(line)
        if command.wait_complete(60) == -1:
            raise RuntimeError("MDI did not complete: " + line)
        drain_errors()
    wait_for(settled, "the joints to stop after " + commands[-1], 5.0)
    # Read once everything stayed still for SETTLE_S.
    time.sleep(SETTLE_S)
    wait_for(settled, "the joints to stop after " + commands[-1], 5.0)
    return joints()


def main():
    component = hal.component("axcheck_probe")
    component.ready()
    with open("probes.json") as f:
        probes = json.load(f)
    command.state(linuxcnc.STATE_ESTOP_RESET)
    command.state(linuxcnc.STATE_ON)
    wait_for(lambda: stat.task_state == linuxcnc.STATE_ON, "machine on")
    command.home(-1)
    wait_for(lambda: all(stat.homed[:JOINTS]), "homing")
    command.mode(linuxcnc.MODE_MDI)
    command.wait_complete()
    results = [probe(p) for p in probes]
    drain_errors()
    return {"probes": results, "errors": messages}


if __name__ == "__main__":
    try:
        out = main()
        code = 0
    except Exception:
        drain_errors()
        out = {"failure": traceback.format_exc(), "errors": messages}
        code = 1
    with open("results.json", "w") as f:
        json.dump(out, f)
    sys.exit(code)
