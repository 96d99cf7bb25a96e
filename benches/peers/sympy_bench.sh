#!/bin/sh
# The symbolic engine against SymPy 1.14 on the Möbius identity of
# benches/poly.rs: criterion for ours, benches/peers/sympy_mobius.py for the
# peer (in a venv under /tmp, created on first use; never run in CI), then
# one table. Run from the repository root:
#     benches/peers/sympy_bench.sh
set -eu
VENV="${SYMPY_VENV:-/tmp/exact-bezier-sympy-venv}"
if [ ! -x "$VENV/bin/python" ]; then
    python3 -m venv "$VENV"
    "$VENV/bin/pip" install --quiet 'sympy==1.14.0'
fi
cargo bench --bench poly -- --warm-up-time 1 --measurement-time 2 >&2
"$VENV/bin/python" benches/peers/sympy_mobius.py --criterion target/criterion
