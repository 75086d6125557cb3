#!/usr/bin/env bash
# The Python package's tests, as CI runs them (README "Python"): the wheel built from this
# checkout by maturin, installed in a fresh virtual environment, then its tests (the same
# numbers as the command line, which `cargo test --release` has built) and `mypy --strict`
# on the package and its examples; the tutorial notebook is executed by nbclient.
set -euo pipefail
cd "$(dirname "$0")"
venv=$(mktemp -d)/venv
wheels=$(mktemp -d)
trap 'rm -rf "$(dirname "$venv")" "$wheels"' EXIT
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check "maturin>=1.9,<2" pytest pandas polars mypy nbclient nbformat ipykernel
"$venv/bin/maturin" build --release --quiet -o "$wheels"
"$venv/bin/pip" install --quiet --disable-pip-version-check "$wheels"/axcheck-*.whl
# The package as installed, not the source folder beside the tests.
(cd "$(dirname "$venv")" && "$venv/bin/python" -m pytest -q -p no:cacheprovider "$OLDPWD/tests")
"$venv/bin/python" -m mypy --strict --no-incremental examples axcheck
(cd .. && "$venv/bin/python" python/examples/table2.py)
