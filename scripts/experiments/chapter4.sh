#!/usr/bin/env bash
# The multistability experiments of thesis Chapter 4 (§4.2-4.3, Figs 4.5-4.8) with the example
# configurations in examples/chapter4/: one system (ẽ = 0.6, ν = 0.05, N = 20000, U = 100,
# Lees–Edwards), five histories —
#   quasihomogeneous  cold start, T_i = 0.1 T₀ (Fig 4.5)
#   plugged           hot start, T_i = 10⁵ T₀ (Fig 4.6)
#   ramp_from_rest    static gas, U(t) = U₀(1 − e^{−t/τ}), τ = 0.5 (Figs 4.7 at c = 20, 4.8 later)
#   kick              the quasihomogeneous flow with 3 periods of A sin(2πt/P), A = U₀, P = 0.3
#   step              the quasihomogeneous flow with U: 100 → 200 at t = 0.1
# then, per run, the space–time picture of ρ(y, t), V_x(y, t), T(y, t) (granule plot spacetime),
# configuration pictures, and a table of the flow-state measures of the last sample
# (summary.json "flow_classification"; docs/macrostructure.md defines them).
#
# Usage: scripts/experiments/chapter4.sh [OUT_DIR]          (default chapter4)
# Cost: ~1-3 min of simulation per run on one core; ~0.5 GB of snapshots in total.
set -euo pipefail
out=${1:-chapter4}
here=$(cd "$(dirname "$0")/../.." && pwd)
granule=${GRANULE:-$here/build/release/granule}
examples=$here/examples/chapter4
mkdir -p "$out"

run() {  # name [extra --set ...]
  local name=$1
  shift
  if [[ ! -f "$out/$name/summary.json" ]]; then
    "$granule" run "$examples/$name.toml" --out "$out/$name" --force "$@" > "$out/$name.log"
  fi
  "$granule" plot spacetime "$out/$name" --out "$out/${name}_spacetime.png" > /dev/null
  "$granule" plot config "$out/$name" --color speed --relative --out "$out/${name}_final.png" > /dev/null
}

run quasihomogeneous
run plugged
run ramp_from_rest
"$granule" plot config "$out/ramp_from_rest" --frame 4 --color speed --relative --out "$out/ramp_from_rest_c20.png" > /dev/null
run kick --set "initial.from=\"$out/quasihomogeneous\""
run step --set "initial.from=\"$out/quasihomogeneous\""

/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
keys = ["density_contrast", "density_rms_deviation", "densest_band_mass_fraction", "velocity_profile_deviation",
        "largest_cluster_mass_fraction"]
print(f"{'run':18s} {'c':>6s} " + " ".join(f"{k[:22]:>22s}" for k in keys))
for name in ["quasihomogeneous", "plugged", "ramp_from_rest", "kick", "step"]:
    s = json.load(open(f"{out}/{name}/summary.json"))
    flow = s.get("flow_classification", {})
    print(f"{name:18s} {flow.get('c', float('nan')):6.1f} " + " ".join(f"{flow.get(k, float('nan')):22.4f}" for k in keys))
PY
