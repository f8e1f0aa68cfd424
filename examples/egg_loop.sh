#!/usr/bin/env bash
# A wheel's vertical loop inside an egg standing on its blunt end (egg.csv:
# the meridian rho = 3 sin u, z = 4 cos u + 0.8 cos^2 u, 801 points from the
# bottom to the top; docs/surfaces.md eqs. S9-S12).  The pointed top bends
# tighter than the blunt bottom, and the least top speed is not the top's
# own sqrt(g / kappa_C): the wheel would first leave the wall some way down
# the descent, where gravity pulls it off a wall that bends less.  Prints,
# per top speed, the status, the least top speed, the friction needed at
# the worst point and the lap time.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
deathsphere vertical --surface profile --profile "$here/egg.csv" --theta 90 --v-top 14:30:4km/h \
    --mu 0.8 --no-stability --format csv \
  | awk -F, '
      NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i
                print "v_top_m_s,status,v_top_min_m_s,mu_required,period_s"; next }
      { print $col["v_cm_m_s"] "," $col["status"] "," $col["v_top_min_m_s"] "," $col["mu_required"] "," \
              $col["period_s"] }'
