#!/usr/bin/env bash
# The standalone suite's subset on every other CPython a ROS 2 user has (3.10, 3.12, 3.13, 3.14).
#
#   bash tools/other_pythons.sh LOG_DIR
#
# Which interpreters: TF_DEMO_PYTHONS (paths, space-separated) when set; otherwise, for each of
# 3.10, 3.12, 3.13 and 3.14, the newest pyenv version "$(pyenv root)/versions/3.X.*" (called by
# path: the shims refuse versions not selected), else python3.X on PATH. It says which it ran
# and which it did not find.
#
# For each one: a virtual environment (.venv-py3.X), the numpy its platform ships (1.21 on 3.10
# as Humble's Ubuntu 22.04, 1.26 on 3.12 as Jazzy's Ubuntu 24.04, 2.x on 3.13 and 3.14), a wheel
# of this package built for that interpreter (compiled with mypyc, as a user's pip builds it),
# installed with its [dds] extra and the test tools; the [bag] and [view] extras and pinocchio
# where they install (the tests that need one skip, saying so). Then SUBSET: every package of
# tf_demo and a process test of every executable. Each interpreter's pytest summary line is
# printed and appended to LOG_DIR/pythons.txt; any failure fails the run (exit 1).
set -euo pipefail

logs="${1:?usage: bash tools/other_pythons.sh LOG_DIR}"
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"
pip_quiet=(-q --disable-pip-version-check)

#: The tests each interpreter runs: the core, URDF, bags (the codec's decoders), the build's own
#: checks, the ROS-compatible Buffer, the node API's shutdown, every node over DDS (the codec both
#: ways), and every executable started as a process and stopped (test_double_ctrl_c, one of its
#: two pauses). Hypothesis runs its derandomised 'matrix' profile (a tenth of CI's examples):
#: these runs look for what an interpreter or a numpy breaks; the whole suite on 3.11 looks for
#: the rest.
SUBSET=(
  test/core test/urdf test/bag test/test_build_info.py test/ros/test_buffer.py
  test/transport/test_shutdown.py test/nodes/test_nodes_dds.py test/cli/test_double_ctrl_c.py
)
SUBSET_FILTER='not 0.005'

numpy_for() {
  case "$1" in
    3.10) echo 'numpy==1.21.6' ;;
    3.12) echo 'numpy==1.26.4' ;;
    *) echo 'numpy>=2,<3' ;;
  esac
}

find_python() {
  local minor="$1" root candidate
  if command -v pyenv >/dev/null 2>&1; then
    root="$(pyenv root)"
    candidate="$(ls -d "$root/versions/$minor".* 2>/dev/null | sort -V | tail -n 1 || true)"
    if [ -n "$candidate" ] && [ -x "$candidate/bin/python$minor" ]; then
      echo "$candidate/bin/python$minor"
      return
    fi
  fi
  candidate="$(command -v "python$minor" || true)"
  if [ -n "$candidate" ] && "$candidate" -c '' >/dev/null 2>&1; then
    echo "$candidate"
  fi
}

pythons=()
if [ -n "${TF_DEMO_PYTHONS:-}" ]; then
  read -r -a pythons <<<"$TF_DEMO_PYTHONS"
else
  missing=()
  for minor in 3.10 3.12 3.13 3.14; do
    found="$(find_python "$minor")"
    if [ -n "$found" ]; then pythons+=("$found"); else missing+=("$minor"); fi
  done
  if [ "${#missing[@]}" -gt 0 ]; then
    echo "== other Pythons: not found: ${missing[*]} (pyenv versions, python3.X on PATH, or TF_DEMO_PYTHONS)" \
      | tee -a "$logs/pythons.txt"
  fi
fi

status=0
for python in "${pythons[@]}"; do
  version="$("$python" -c 'import sys; print("%d.%d" % sys.version_info[:2])')"
  full="$("$python" -c 'import platform; print(platform.python_version())')"
  venv="$here/.venv-py$version"
  log="$logs/python$version.log"
  echo "== CPython $full ($python): venv, $(numpy_for "$version"), a wheel built for it, pytest subset"
  (
    set -e
    [ -x "$venv/bin/python" ] || "$python" -m venv "$venv"
    "$venv/bin/python" -m pip install "${pip_quiet[@]}" --upgrade pip
    constraints="$logs/constraints-$version.txt"
    numpy_for "$version" >"$constraints"
    "$venv/bin/python" -m pip install "${pip_quiet[@]}" -c "$constraints" numpy
    wheels="$logs/wheels-$version"
    rm -rf "$wheels"
    "$venv/bin/python" -m pip wheel "${pip_quiet[@]}" --no-deps -w "$wheels" . 2>&1 \
      | grep -E '^tf_demo: ' || true
    wheel="$(ls "$wheels"/tf_demo-*.whl)"
    echo "   wheel: $(basename "$wheel")"
    "$venv/bin/python" -m pip uninstall "${pip_quiet[@]}" -y tf_demo >/dev/null 2>&1 || true
    "$venv/bin/python" -m pip install "${pip_quiet[@]}" -c "$constraints" "$wheel[dds]" \
      'pytest>=7' pytest-timeout 'hypothesis>=6.80'
    for optional in "$wheel[bag]" "$wheel[view]" 'pin>=2.7'; do
      "$venv/bin/python" -m pip install "${pip_quiet[@]}" -c "$constraints" "$optional" \
        >"$logs/optional-$version.log" 2>&1 \
        || echo "   not installable on $version: ${optional#"$wheel"} ($(grep -m1 -E 'ERROR' "$logs/optional-$version.log" || echo 'pip failed'))"
    done
  ) 2>&1 | { grep -v "^WARNING: Location" || true; } | tee "$log.setup" || { echo "CPython $version: setup failed" >&2; status=1; continue; }
  build_line="$(cd / && "$venv/bin/python" -m tf_demo)"
  echo "   $build_line"
  test_status=0
  # The pytest script (not python -m pytest): the working directory stays off sys.path, so the
  # tests import the installed wheel, not this checkout's sources.
  (
    cd "$here"
    env -u PYTHONPATH -u AMENT_PREFIX_PATH -u RMW_IMPLEMENTATION -u ROS_DISTRO \
      PATH="$venv/bin:$PATH" VIRTUAL_ENV="$venv" TF_DEMO_BACKEND=dds \
      TF_DEMO_HYPOTHESIS_PROFILE=matrix \
      "$venv/bin/pytest" "${SUBSET[@]}" -k "$SUBSET_FILTER" -p no:cacheprovider -q
  ) >"$log" 2>&1 || test_status=$?
  summary="$(grep -E '^=+ .*(passed|failed|error|errors|skipped|no tests ran).* in [0-9.]+s' "$log" \
    | tail -n 1 || true)"
  if [ -z "$summary" ]; then
    summary="$(tail -n 1 "$log")"
  fi
  if [ "$test_status" != 0 ] || [[ "$build_line" != *", compiled ("* ]]; then
    grep -E '^(FAILED|ERROR) ' "$log" | head -n 30 || true
    status=1
  fi
  echo "== CPython $full, $build_line, numpy $("$venv/bin/python" -c 'import numpy; print(numpy.__version__)'): $summary" \
    | tee -a "$logs/pythons.txt"
done
exit "$status"
