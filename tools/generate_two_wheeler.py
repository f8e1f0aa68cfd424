"""Regenerate ``deathsphere/physics/two_wheeler/_generated.py``: derive the
Whipple bicycle's equations with sympy (``deathsphere.physics.two_wheeler.derivation``,
docs/two-wheeler.md sec. 5) and write them as numpy code (``deathsphere.codegen``).
The physics package only derives; this script reports and writes (whole
or not at all).

    python tools/generate_two_wheeler.py            # derive and report
    python tools/generate_two_wheeler.py --write    # and rewrite _generated.py
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from deathsphere.codegen import GENERATED, generated_source
from deathsphere.physics.two_wheeler.derivation import SURFACES, derive
from deathsphere.writers.atomic import atomic_file


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--write", action="store_true", help="rewrite _generated.py")
    parser.add_argument("--output", type=Path, default=GENERATED, help="where --write writes")
    parser.add_argument("--surface", action="append", choices=SURFACES,
                        help="a surface to generate (repeatable; default: all)")
    args = parser.parse_args(argv)
    surfaces = tuple(args.surface or SURFACES)
    start = time.perf_counter()
    derivations = {s: derive(s) for s in surfaces}
    for s, d in derivations.items():
        print(f"{s}: derived in {d.seconds:.1f} s")
    text = generated_source(surfaces, derivations)
    print(f"generated in {time.perf_counter() - start:.1f} s in all, {len(text.splitlines())} lines")
    if args.write:
        with atomic_file(args.output, "w", encoding="utf-8") as out:
            out.write(text)
        print(f"wrote {args.output}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
