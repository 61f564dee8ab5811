rm -rf /tmp/peaks && mkdir -p /tmp/peaks
for f in scenarios/*.toml; do n=$(basename $f .toml); ./target/release/scara run scenario $f --out /tmp/peaks/$n >/dev/null 2>&1 || echo "FAIL $f"; done
for t in position contact three-zone hybrid; do ./target/release/scara run $t --out /tmp/peaks/cmd-$t >/dev/null 2>&1 || echo "FAIL $t"; done
python3 - <<'PY'
import json,glob,os
for m in sorted(glob.glob('/tmp/peaks/**/metrics.json',recursive=True)):
    j=json.load(open(m))
    p=j.get('safety_peaks')
    name=m[len('/tmp/peaks/'):-len('/metrics.json')]
    if not p: print(name,'no peaks'); continue
    jl=min(b for a,b in p['joint_limit_distance'])
    js=max(b for a,b in p['joint_speed'])
    ts=max(b for a,b in p['torque_step'])
    ts=max(b for a,b in p['torque_step']); print(f"{name:40s} trips={[t['cause']+'@'+str(round(t['t_s'],3)) for t in j['safety_trips']]} F {p['force_n'][1]:.0f}/{p['force_n'][0]:.0f} rate {p['force_rate_n_s'][1]:.0f} osc {p['oscillation_rms_n'][1]:.2f}/{p['oscillation_rms_n'][0]} v {p['tool_speed_m_s'][1]:.2f} box {p['outside_workspace_m']:.3f} jl {jl:.3f} js {js:.2f} ts {ts:.1f} rl {j['torque_rate_limited_samples']}")
PY
