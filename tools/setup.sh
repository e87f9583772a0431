#!/usr/bin/env bash
# Set up tf_demo on a fresh Debian 12 machine (Python 3.11, no ROS) and run one job.
#
#   bash tools/setup.sh demo [SECONDS]   live demo: static_tf_pub, dynamic_tf_pub, tf_listener, tf_echo
#   bash tools/setup.sh test             the whole test suite, in both worlds
#
# It installs what it needs itself: Debian packages (apt), a virtual environment in .venv and the
# pip packages (this package with its [dds,view] extras for the demo, all of them for the
# tests). Exit status is the job's. The install
# compiles the hot modules with mypyc (TF_DEMO_INTERPRETED=1 runs them from their sources).
#
# The test job runs the standalone suite (pytest in .venv, no ROS) on the compiled build, then
# the core's and the codec's tests on the interpreted build, then a subset on every other CPython
# it finds (tools/other_pythons.sh: 3.10, 3.12, 3.13, 3.14, each from a wheel built for it);
# then, where ROS 2 Jazzy is installed (/opt/ros/jazzy/setup.bash), the ROS-world suite: colcon build + colcon test in an
# overlay workspace on that Jazzy (compiled too), with a virtual environment of the system Python
# that sees Jazzy's rclpy (.venv-jazzy, --system-site-packages) and has no cyclonedds Python
# package, and again the core's and the codec's tests interpreted. A failure anywhere fails the
# run; every pytest summary line is printed.
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
jazzy_setup="${TF_DEMO_JAZZY_SETUP:-/opt/ros/jazzy/setup.bash}"

sudo_cmd=()
if [ "$(id -u)" != 0 ]; then sudo_cmd=(sudo); fi

apt_packages=(python3 python3-venv python3-dev gcc graphviz)
if [ "$job" = test ]; then
  # Oracles and peers for the tests: tf2's C++ core (python3-tf2, run by /usr/bin/python3) and
  # Cyclone DDS 0.10 (C library and idlc) for the foreign-peer interop test.
  apt_packages+=(python3-tf2 cyclonedds-dev cyclonedds-tools)
  # A real browser for tf_view's tests: Debian's chromium, driven through its chromedriver.
  apt_packages+=(chromium chromium-driver)
  if [ -f "$jazzy_setup" ]; then
    # The rosdep keys of package.xml's exec_depend and test_depend, as a ROS user installs them.
    apt_packages+=(python3-numpy python3-yaml python3-lxml python3-pytest python3-hypothesis)
  fi
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

pip_quiet=(-q --disable-pip-version-check)
venv="$here/.venv"
if [ ! -x "$venv/bin/python" ]; then
  echo "== python3 -m venv .venv"
  python3 -m venv "$venv"
fi
# The demo installs what it runs (the DDS backend and tf_view); the tests need all the extras.
pip_packages=(-e ".[dds,view]")
if [ "$job" = test ]; then pip_packages=(-e ".[dds,test,view,bag,docs]" colcon-common-extensions); fi
echo "== pip install ${pip_packages[*]} (mypyc compiles the hot modules)"
"$venv/bin/python" -m pip install "${pip_quiet[@]}" --upgrade pip
"$venv/bin/python" -m pip install "${pip_quiet[@]}" "${pip_packages[@]}"
build_line="$("$venv/bin/python" -m tf_demo)"
echo "== $build_line"
if [ "$job" = test ] && [[ "$build_line" != *", compiled ("* ]]; then
  # gcc and python3-dev are installed above: a build that fell back to interpreted is a failure
  # here (the suite would pass on the interpreted build and hide it).
  echo "the install did not compile the hot modules: $build_line" >&2
  exit 1
fi

if [ "$job" = demo ]; then
  export PATH="$venv/bin:$PATH"
  export VIRTUAL_ENV="$venv"
  # Loopback-only discovery and a private domain keep the demo off the user's network.
  export ROS_AUTOMATIC_DISCOVERY_RANGE="${ROS_AUTOMATIC_DISCOVERY_RANGE:-LOCALHOST}"
  export ROS_DOMAIN_ID="${ROS_DOMAIN_ID:-42}"
  exec tf_demo_live --duration "${2:-20}"
fi

# pytest's closing line ("=== 12 passed, 3 skipped in 4.56s ===") from a log.
summary_line() {
  grep -E '^=+ .*(passed|failed|error|errors|skipped|deselected|no tests ran).* in [0-9.]+s' "$1" \
    | tail -n 1 || true
}

logs="$(mktemp -d)"
trap 'kill "${pythons_pid:-}" 2>/dev/null || true; rm -rf "$logs"' EXIT

# -- the standalone world: no ROS, the DDS backend ----------------------------------------------
echo "== standalone world: pytest (TF_DEMO_BACKEND=dds)"
standalone_status=0
env -u PYTHONPATH -u AMENT_PREFIX_PATH -u RMW_IMPLEMENTATION -u ROS_DISTRO \
  PATH="$venv/bin:$PATH" VIRTUAL_ENV="$venv" TF_DEMO_BACKEND=dds \
  "$venv/bin/python" -m pytest test -p no:cacheprovider 2>&1 | tee "$logs/standalone.log" \
  || standalone_status=$?  # pipefail: pytest's own exit status
standalone_summary="$(summary_line "$logs/standalone.log")"
# pytest exits 5 when it collects nothing: that is a failure here.
if [ -z "$standalone_summary" ] || [ "$standalone_status" = 5 ]; then
  standalone_status=1
fi

# The same core and codec tests (differential tests included) on the interpreted build.
interpreted_tests=(test/core test/msgs)
echo "== standalone world, interpreted build: pytest ${interpreted_tests[*]} (TF_DEMO_INTERPRETED=1)"
interpreted_status=0
env -u PYTHONPATH -u AMENT_PREFIX_PATH -u RMW_IMPLEMENTATION -u ROS_DISTRO \
  PATH="$venv/bin:$PATH" VIRTUAL_ENV="$venv" TF_DEMO_BACKEND=dds TF_DEMO_INTERPRETED=1 \
  "$venv/bin/python" -m pytest "${interpreted_tests[@]}" -p no:cacheprovider 2>&1 \
  | tee "$logs/interpreted.log" || interpreted_status=$?
interpreted_summary="$(summary_line "$logs/interpreted.log")"
if [ -z "$interpreted_summary" ] || [ "$interpreted_status" = 5 ]; then
  interpreted_status=1
fi

# -- every other CPython found (3.10, 3.12, 3.13, 3.14): a wheel each, the standalone subset ----
# They run beside the ROS world below (both mostly wait on processes and DDS: together they keep
# the two cores busy, and the run within CI's time); their output follows the ROS world's.
echo "== other Pythons: bash tools/other_pythons.sh, beside the ROS world (output after it)"
pythons_status=0
bash tools/other_pythons.sh "$logs" >"$logs/pythons.log" 2>&1 &
pythons_pid=$!

# -- the ROS world: colcon build + colcon test in an overlay on ROS 2 Jazzy ---------------------
ros_status=0
ros_summary=''
if [ -f "$jazzy_setup" ]; then
  jazzy_venv="$here/.venv-jazzy"
  ws="$here/.jazzy_ws"
  mkdir -p "$ws"
  touch "$ws/COLCON_IGNORE"
  if [ ! -x "$jazzy_venv/bin/python" ]; then
    echo "== /usr/bin/python3 -m venv --system-site-packages .venv-jazzy"
    /usr/bin/python3 -m venv --system-site-packages "$jazzy_venv"
  fi
  touch "$jazzy_venv/COLCON_IGNORE"
  # The pip-only dependencies (yourdfpy, xacro) and test tools; never cyclonedds: a ROS user does
  # not have it. numpy stays the system's, which Jazzy's message libraries were built against
  # (so no pinocchio here: its wheels need numpy >= 1.26; the kinematics oracle runs standalone).
  constraints="$logs/constraints.txt"
  /usr/bin/python3 -c 'import numpy; print(f"numpy=={numpy.__version__}")' >"$constraints"
  echo "== pip install (ROS world): yourdfpy xacro viser rosbags matplotlib pytest-timeout ruff mypy selenium colcon"
  "$jazzy_venv/bin/python" -m pip install "${pip_quiet[@]}" -c "$constraints" \
    'yourdfpy>=0.0.56' xacro 'pytest>=7,<8' pytest-timeout 'hypothesis>=6.80' 'ruff==0.17.5' 'mypy>=1.10' types-PyYAML \
    'viser>=1.0' pycollada 'rosbags>=0.10' 'matplotlib>=3.6' mcap 'selenium>=4.10' pillow colcon-common-extensions
  echo "== ROS world: colcon build + colcon test on $(dirname "$jazzy_setup")"
  (
    set +u
    # shellcheck disable=SC1090
    source "$jazzy_setup"
    set -u
    export PATH="$jazzy_venv/bin:$PATH" VIRTUAL_ENV="$jazzy_venv"
    export RMW_IMPLEMENTATION="${RMW_IMPLEMENTATION:-rmw_cyclonedds_cpp}"
    export TF_DEMO_STANDALONE_PYTHON="$venv/bin/python"
    unset TF_DEMO_BACKEND
    cd "$ws"
    rm -rf build/tf_demo install/tf_demo
    # colcon through the venv's Python (ROS 2's advice for venvs): the executables' shebang is
    # then that Python, which sees the pip-only dependencies (mypy among them: setup.py compiles).
    python -m colcon build --base-paths "$here" --packages-select tf_demo \
      --event-handlers console_cohesion- >"$logs/ros_build.log" 2>&1 \
      || { cat "$logs/ros_build.log"; exit 1; }
    grep -E '^tf_demo: ' "$logs/ros_build.log" || true
    set +u
    # shellcheck disable=SC1091
    source install/setup.bash
    set -u
    # The tests import the installed (compiled) package: colcon runs `python -m pytest` in the
    # source folder, whose tf_demo/ would otherwise come first on sys.path.
    export PYTHONSAFEPATH=1
    ros_build_line="$(cd / && python -m tf_demo)"
    echo "== $ros_build_line"
    if [[ "$ros_build_line" != *", compiled ("* ]]; then
      echo "colcon build did not compile the hot modules: $ros_build_line" >&2
      exit 1
    fi
    status=0
    python -m colcon test --base-paths "$here" --packages-select tf_demo \
      --return-code-on-test-failure \
      --event-handlers console_direct+ --pytest-args -p no:cacheprovider || status=$?
    python -m colcon test-result --all --verbose || true
    exit "$status"
  ) 2>&1 | tee "$logs/ros.log" || ros_status=$?
  ros_summary="$(summary_line "$logs/ros.log")"
  if [ -z "$ros_summary" ] || grep -qE '^Summary: 0 tests' "$logs/ros.log"; then
    ros_status=1
  fi
  # The core only: the codec is never compiled, and its tests ran interpreted above.
  ros_interpreted_tests=(test/core)
  echo "== ROS world, interpreted build: pytest ${ros_interpreted_tests[*]} (TF_DEMO_INTERPRETED=1)"
  ros_interpreted_status=0
  (
    set +u
    # shellcheck disable=SC1090
    source "$jazzy_setup"
    # shellcheck disable=SC1091
    source "$ws/install/setup.bash"
    set -u
    export PATH="$jazzy_venv/bin:$PATH" VIRTUAL_ENV="$jazzy_venv" PYTHONSAFEPATH=1
    export RMW_IMPLEMENTATION="${RMW_IMPLEMENTATION:-rmw_cyclonedds_cpp}"
    export TF_DEMO_INTERPRETED=1
    unset TF_DEMO_BACKEND
    python -m pytest "${ros_interpreted_tests[@]}" -p no:cacheprovider
  ) 2>&1 | tee "$logs/ros_interpreted.log" || ros_interpreted_status=$?
  ros_interpreted_summary="$(summary_line "$logs/ros_interpreted.log")"
  if [ -z "$ros_interpreted_summary" ] || [ "$ros_interpreted_status" = 5 ]; then
    ros_interpreted_status=1
  fi
fi

wait "$pythons_pid" || pythons_status=$?
echo "== other Pythons (run beside the ROS world):"
cat "$logs/pythons.log"

echo
echo "== standalone world: ${standalone_summary:-no pytest summary (the suite did not run)}"
echo "== standalone world, interpreted (${interpreted_tests[*]}): ${interpreted_summary:-no pytest summary}"
if [ -f "$logs/pythons.txt" ]; then
  cat "$logs/pythons.txt"
fi
if [ -f "$jazzy_setup" ]; then
  echo "== ROS world (rclpy, $(dirname "$jazzy_setup")): ${ros_summary:-no pytest summary}"
  echo "== ROS world, interpreted (${ros_interpreted_tests[*]}): ${ros_interpreted_summary:-no pytest summary}"
else
  echo "== ROS world: not run ($jazzy_setup not found; install ROS 2 Jazzy to run it)"
fi
status=0
if [ "$standalone_status" != 0 ]; then
  echo "standalone suite failed (exit $standalone_status)" >&2
  status=1
fi
if [ "$interpreted_status" != 0 ]; then
  echo "standalone interpreted run failed (exit $interpreted_status)" >&2
  status=1
fi
if [ "$pythons_status" != 0 ]; then
  echo "a run on another CPython failed (exit $pythons_status)" >&2
  status=1
fi
if [ "$ros_status" != 0 ]; then
  echo "ROS-world suite failed (exit $ros_status)" >&2
  status=1
fi
if [ "${ros_interpreted_status:-0}" != 0 ]; then
  echo "ROS-world interpreted run failed (exit $ros_interpreted_status)" >&2
  status=1
fi
exit "$status"
