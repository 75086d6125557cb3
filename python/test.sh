#!/usr/bin/env bash
# The Python package's tests, as CI runs them (README "Python"): the wheel built from this
# checkout by maturin, installed in a fresh virtual environment, then its tests (the same
# numbers as the command line, which `cargo test --release` has built) and `mypy --strict`
# on the package and its examples; the tutorial notebook is executed by nbclient. Then the
# same wheel and tests on CPython 3.9, the oldest the abi3 wheel is for (Debian bullseye's,
# unpacked by py39.sh).
set -euo pipefail
cd "$(dirname "$0")"
tmp=$(mktemp -d)
venv=$tmp/venv
wheels=$tmp/wheels
trap 'rm -rf "$tmp"' EXIT
python3 -m venv "$venv"
"$venv/bin/pip" install --quiet --disable-pip-version-check "maturin>=1.9,<2" pytest pandas polars mypy nbclient nbformat ipykernel
"$venv/bin/maturin" build --release --quiet -o "$wheels"
"$venv/bin/pip" install --quiet --disable-pip-version-check "$wheels"/axcheck-*.whl
# The package as installed, not the source folder beside the tests.
(cd "$(dirname "$venv")" && "$venv/bin/python" -m pytest -q -p no:cacheprovider "$OLDPWD/tests")
"$venv/bin/python" -m mypy --strict --no-incremental examples axcheck
(cd .. && "$venv/bin/python" python/examples/table2.py)

# CPython 3.9: the wheel's tests (the notebook included) on the oldest Python it is for.
if command -v apt-get >/dev/null; then
  py39=$(bash py39.sh "$tmp/py39" | tail -1)
  "$py39" -m venv "$tmp/venv39"
  "$tmp/venv39/bin/pip" install --quiet --disable-pip-version-check pytest pandas polars nbclient nbformat ipykernel "$wheels"/axcheck-*.whl
  (cd "$tmp" && "$tmp/venv39/bin/python" -c 'import sys; assert sys.version_info[:2] == (3, 9), sys.version' \
    && "$tmp/venv39/bin/python" -m pytest -q -p no:cacheprovider "$OLDPWD/tests")
else
  echo "python/test.sh: no apt-get, the tests on CPython 3.9 (Debian bullseye's) were not run" >&2
fi
