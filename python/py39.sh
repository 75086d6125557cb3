#!/usr/bin/env bash
# py39.sh DIR — make Debian bullseye's CPython 3.9 runnable from DIR on a newer
# Debian (bookworm), without installing it into the system: the .debs are fetched
# with a private apt configuration (signatures checked against the Debian archive
# keyring), unpacked with `dpkg -x` (no dpkg database change) and the interpreter
# gets an RPATH to its own bundled libs (libssl1.1, libffi7, libmpdec3), so that
# venvs made from it work without LD_LIBRARY_PATH. Prints the interpreter's path
# on its last line. Idempotent: exits at once if DIR/bin/python3.9 already works.
set -euo pipefail
[ $# -eq 1 ] || { echo "usage: $0 DIR" >&2; exit 2; }
mkdir -p "$1"; DIR=$(cd "$1" && pwd)
PY="$DIR/bin/python3.9"
works() { "$PY" -c 'import ssl, sqlite3, venv, ctypes, ensurepip, distutils.util' >/dev/null 2>&1; }
if works; then echo "$PY"; exit 0; fi

# Debian bullseye packages for python3.9 with ssl/venv/pip; the rest of its
# libraries (libc, zlib, expat, sqlite3, readline, ...) are bookworm's, same sonames.
PKGS="python3.9-minimal libpython3.9-minimal libpython3.9-stdlib python3.9 python3.9-venv
  python3-distutils python3-lib2to3 python-pip-whl libssl1.1 libffi7 libmpdec3"
command -v patchelf >/dev/null || PKGS="$PKGS patchelf"  # bullseye's, run from the work dir

# Private apt configuration: only bullseye (+ security), own state/cache, host config ignored.
W=$(mktemp -d); trap 'rm -rf "$W"' EXIT
KEYRING=/usr/share/keyrings/debian-archive-keyring.gpg
mkdir -p "$W/parts" "$W/state/lists/partial" "$W/cache/archives/partial" "$W/debs" "$W/x"
touch "$W/status"
cat > "$W/sources.list" <<EOF
deb [signed-by=$KEYRING] http://deb.debian.org/debian bullseye main
deb [signed-by=$KEYRING] http://deb.debian.org/debian-security bullseye-security main
EOF
cat > "$W/apt.conf" <<EOF
Dir::Etc::Main "/dev/null"; Dir::Etc::Parts "$W/parts"; Dir::Etc::Preferences "/dev/null";
Dir::Etc::PreferencesParts "$W/parts"; Dir::Etc::SourceList "$W/sources.list";
Dir::Etc::SourceParts "$W/parts"; Dir::State "$W/state"; Dir::State::status "$W/status";
Dir::Cache "$W/cache"; APT::Architecture "amd64"; APT::Architectures { "amd64"; };
Acquire::Languages "none"; APT::Sandbox::User "root";
EOF
export APT_CONFIG="$W/apt.conf"
apt-get -qq update >&2
(cd "$W/debs" && apt-get -qq download $PKGS >&2)   # newest version, security suite included

# Unpack into DIR (plain file extraction, no maintainer scripts, no dpkg database).
for deb in "$W"/debs/*.deb; do
  case "$deb" in */patchelf_*) dpkg -x "$deb" "$W/x" ;; *) dpkg -x "$deb" "$DIR" ;; esac
done
PATCHELF=$(command -v patchelf || echo "$W/x/usr/bin/patchelf")

# DT_RPATH (not RUNPATH) on the executable also serves the extension modules it
# dlopens (_ssl, _ctypes, _decimal) and their deps; $ORIGIN follows venv symlinks.
"$PATCHELF" --force-rpath --set-rpath '$ORIGIN/../lib/x86_64-linux-gnu' "$DIR/usr/bin/python3.9"

# Debian's ensurepip reads wheels from a hard-coded /usr/share/python-wheels:
# point it at the extracted ones (sys.base_prefix is DIR/usr, in a venv too).
sed -i "s#'/usr/share/python-wheels#os.path.join(sys.base_prefix, 'share', 'python-wheels') + '#g" \
  "$DIR/usr/lib/python3.9/ensurepip/__init__.py"

# Wrapper: exec the real binary by its own path, so sys.executable (and hence a
# venv's "home") is DIR/usr/bin, where the stdlib is found next to it.
mkdir -p "$DIR/bin"
cat > "$PY" <<'EOF'
#!/bin/sh
d=$(dirname "$(readlink -f "$0")"); exec "${d%/bin}/usr/bin/python3.9" "$@"
EOF
chmod +x "$PY"; ln -sf python3.9 "$DIR/bin/python3"
"$PY" -m compileall -q -j0 "$DIR/usr/lib/python3.9" >/dev/null 2>&1 || true   # faster first start

works || { echo "py39.sh: $PY does not work" >&2; "$PY" -c 'import ssl, sqlite3, venv, ctypes'; exit 1; }
"$PY" -c 'import sys, ssl; print(sys.version.split()[0], ssl.OPENSSL_VERSION)' >&2
echo "$PY"
