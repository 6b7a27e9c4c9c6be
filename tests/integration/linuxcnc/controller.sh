# The tests' (and the capture benchmark's) LinuxCNC controller, sourced after lib.sh: LinuxCNC's
# sample simulated mill (mm) run headless as an ordinary user (LinuxCNC refuses root), with
# linuxcncrsh as its display (no window), no manual tool change dialog (the HAL loops tool change
# back), fast axes. Sets: user, cfg (its folder: mill.ini, tools.tbl, nc/), python, drive;
# functions start_controller, stop_controller, as_user.
# Needs root (to make the user) and LinuxCNC (Debian linuxcnc-uspace).
here=$(dirname "${BASH_SOURCE[0]}")
# LinuxCNC's Python module is installed for Debian's Python, whatever python3 is first on PATH.
python=/usr/bin/python3
user=ncb-cnc  # short: ipcs prints at most 10 characters of an owner
id "$user" > /dev/null 2>&1 || useradd -m "$user"
chmod 755 "$WORK"
cfg=$WORK/lcnc
mkdir -p "$cfg/nc" "$WORK/out"

sample=/usr/share/doc/linuxcnc/examples/sample-configs/sim/axis/axis_mm.ini
sed -e 's/^DISPLAY = .*/DISPLAY = linuxcncrsh/' -e '/axis_manualtoolchange.hal/d' \
    -e 's/^MAX_FEED_OVERRIDE = .*/MAX_FEED_OVERRIDE = 200/' \
    -e 's/^MAX_VELOCITY = .*/MAX_VELOCITY = 4000/' -e 's/^MAX_LINEAR_VELOCITY = .*/MAX_LINEAR_VELOCITY = 6000/' \
    -e 's/^MAX_ACCELERATION = .*/MAX_ACCELERATION = 40000/' -e 's/^MAX_LINEAR_ACCELERATION = .*/MAX_LINEAR_ACCELERATION = 60000/' \
    -e 's/^DEFAULT_LINEAR_ACCELERATION = .*/DEFAULT_LINEAR_ACCELERATION = 40000/' \
    -e 's/^MIN_LIMIT = .*/MIN_LIMIT = -2000/' -e 's/^MAX_LIMIT = .*/MAX_LIMIT = 2000/' \
    -e 's/^FERROR = .*/FERROR = 1000/' -e 's/^MIN_FERROR = .*/MIN_FERROR = 1000/' \
    -e "s#^PROGRAM_PREFIX = .*#PROGRAM_PREFIX = $cfg/nc#" -e 's/^TOOL_TABLE = .*/TOOL_TABLE = tools.tbl/' \
    "$sample" > "$cfg/mill.ini"
# The paper's tools as the controller's tool table.
cat > "$cfg/tools.tbl" <<'TBL'
T1 P1 Z50 D18 ;ENDMILL_18MM
T2 P2 Z70 D20 ;DRILL_20MM
T3 P3 Z50 D22 ;REAMER_22MM
TBL
cp "$here/drive.py" "$cfg/drive.py"
drive=$cfg/drive.py
chown -R "$user" "$cfg"

# Stops the controller as its start script would be stopped (it then unloads HAL and the
# realtime part); what is left after 20 s is killed and HAL's memory unloaded.
stop_controller() {
  pkill -TERM -u "$user" -f "linuxcnc $cfg/mill.ini" 2>/dev/null || true
  for _ in $(seq 1 200); do pgrep -u "$user" > /dev/null || break; sleep 0.1; done
  pkill -KILL -u "$user" 2>/dev/null || true
  su "$user" -c "halrun -U" > /dev/null 2>&1 || true
  # NML's buffers and their semaphores: a controller started over stale ones never hears its IO
  for kind in m s; do
    ipcs -$kind | awk -v u="$user" '$3 == u { print $2 }' | xargs -r -n 1 ipcrm -$kind 2>/dev/null || true
  done
  [[ $(stat -c %U /tmp/linuxcnc.lock 2>/dev/null) == "$user" ]] && rm -f /tmp/linuxcnc.lock
  return 0
}
# as_user CMD...: the shell command that runs CMD as the controller's user (su -c), with this
# test's DDS settings.
as_user() {
  printf 'export CYCLONEDDS_URI=%q NCBRIDGE_DDS_DOMAIN=%q; exec ' "$CYCLONEDDS_URI" "$NCBRIDGE_DDS_DOMAIN"
  printf '%q ' "$@"
}

# start_controller: LinuxCNC up and answering (its output in $WORK/linuxcnc.log).
start_controller() {
  stop_controller  # a controller left by an earlier run
  CLEANUP_HOOKS+=("stop_controller")
  start linuxcnc su "$user" -c "cd '$cfg' && exec script -qfc 'linuxcnc $cfg/mill.ini' '$cfg/linuxcnc.typescript'"
  su "$user" -c "$(as_user timeout 90 "$python" "$drive" wait)" \
    || fail "LinuxCNC did not start: $(tail -n 20 "$cfg/linuxcnc.typescript" 2>/dev/null)"
}
