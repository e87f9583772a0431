#!/usr/bin/env bash
# Set up tf_demo on a fresh Debian 12 machine (Python 3.11, no ROS) and run one job.
#
#   bash tools/setup.sh demo [SECONDS]   live demo: static_tf_pub, dynamic_tf_pub, tf_listener, tf_echo
#   bash tools/setup.sh test             the whole test suite through colcon build + colcon test
#
# It installs what it needs itself: Debian packages (apt), a virtual environment in .venv and the
# pip packages (this package with its [dds,test] extras, colcon). Exit status is the job's.
set -euo pipefail

job="${1:-}"
case "$job" in
  demo | test) ;;
  *)
    echo "usage: bash tools/setup.sh demo [SECONDS] | test" >&2
    exit 2
    ;;
esac

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

sudo_cmd=()
if [ "$(id -u)" != 0 ]; then sudo_cmd=(sudo); fi

apt_packages=(python3 python3-venv python3-dev gcc graphviz)
if [ "$job" = test ]; then
  # Oracles and peers for the tests: tf2's C++ core (python3-tf2, run by /usr/bin/python3) and
  # Cyclone DDS 0.10 (C library and idlc) for the foreign-peer interop test.
  apt_packages+=(python3-tf2 cyclonedds-dev cyclonedds-tools)
fi
missing=()
for package in "${apt_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed' \
    || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "== apt-get install ${missing[*]}"
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq "${missing[@]}" >/dev/null
fi

venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
  echo "== python3 -m venv .venv"
  python3 -m venv "$venv"
fi
echo "== pip install -e .[dds,test] colcon-common-extensions"
"$venv/bin/python" -m pip install -q --disable-pip-version-check --upgrade pip
"$venv/bin/python" -m pip install -q --disable-pip-version-check -e ".[dds,test]" \
  colcon-common-extensions
export PATH="$venv/bin:$PATH"
export VIRTUAL_ENV="$venv"

if [ "$job" = demo ]; then
  # Loopback-only discovery and a private domain keep the demo off the user's network.
  export ROS_AUTOMATIC_DISCOVERY_RANGE="${ROS_AUTOMATIC_DISCOVERY_RANGE:-LOCALHOST}"
  export ROS_DOMAIN_ID="${ROS_DOMAIN_ID:-42}"
  exec tf_demo_live --duration "${2:-20}"
fi

echo "== colcon build"
rm -rf build/tf_demo install/tf_demo
colcon build --event-handlers console_cohesion- --packages-select tf_demo
echo "== colcon test"
status=0
colcon test --packages-select tf_demo --return-code-on-test-failure \
  --event-handlers console_direct+ || status=$?
summary="$(colcon test-result --all --verbose 2>&1 || true)"
echo "$summary"
# pytest exits 5 when it collects nothing; a run that executed no test is a failure here.
if echo "$summary" | grep -qE '^Summary: 0 tests'; then
  echo "no test was executed" >&2
  status=1
fi
if [ "$status" != 0 ]; then
  echo "colcon test failed with exit status $status" >&2
fi
exit "$status"
