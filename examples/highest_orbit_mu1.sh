#!/usr/bin/env bash
# The highest horizontal orbit (smallest theta) a wheel can ride with tyres of
# mu = 1 and a rider who feels at most MAX_G g (default 5; the load load_g =
# |contact force| / (m g), what --max-g limits), found by piping a
# CSV sweep through awk and sort.  Without the g limit the answer creeps to
# theta -> 45 deg as alpha -> 0 at unbounded speed (mu -> cot theta there).
# Columns are looked up by name in the header, so added columns don't break it.
set -euo pipefail
max_g=${MAX_G:-5}
deathsphere sweep --theta 5:90:0.5 --alpha 0.5:60:0.5 --mu 1 --only ok \
  | awk -F, -v max_g="$max_g" '
      NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i
                print "theta_deg,alpha_deg,v_cm_m_s,load_g,mu_required"; next }
      $col["load_g"] <= max_g { print $col["theta_deg"] "," $col["alpha_deg"] "," $col["v_cm_m_s"] "," \
                                      $col["load_g"] "," $col["mu_required"] }' \
  | { IFS= read -r header; echo "$header"; sort -t, -k1,1g -k5,5g | sed -n 1p; }
