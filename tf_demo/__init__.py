# Copyright 2026 The tf_demo Authors
#
# Licensed under the Apache License, Version 2.0 (the "License");
# you may not use this file except in compliance with the License.
# You may obtain a copy of the License at
#
#     http://www.apache.org/licenses/LICENSE-2.0
#
# Unless required by applicable law or agreed to in writing, software
# distributed under the License is distributed on an "AS IS" BASIS,
# WITHOUT WARRANTIES OR CONDITIONS OF ANY KIND, either express or implied.
# See the License for the specific language governing permissions and
# limitations under the License.

"""
tf_demo: tf2 in typed Python for ROS 2 Jazzy and the standalone world.

Its hot modules are compiled by mypyc where the install could (:mod:`tf_demo.build_info` says
which build runs); ``TF_DEMO_INTERPRETED=1`` in the environment runs the Python source instead,
and so does an editable install whose sources changed after the build (with a warning).  A C
extension left beside a module that is not compiled (an older install's) is never imported.
"""

import os as _os
import warnings as _warnings

from tf_demo import build_info as _build_info

_build_info.guard_sources()
if _os.environ.get(_build_info.INTERPRETED_ENVIRONMENT_VARIABLE, '') not in ('', '0'):
    _build_info.prefer_sources()
elif _stale := _build_info.stale_modules():
    _build_info.prefer_sources()
    _warnings.warn(
        f'tf_demo: {", ".join(_stale)} changed after it was compiled: running the Python '
        'sources instead (rebuild with `pip install -e .` or `colcon build`)',
        RuntimeWarning,
        stacklevel=2,
    )
