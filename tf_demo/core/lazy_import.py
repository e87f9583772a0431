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
Modules imported on first use, with the standard library's :class:`importlib.util.LazyLoader`.

numpy takes about a fifth of a node's start-up to import, and most nodes never touch an array
(``static_tf_pub`` publishes one message and sleeps). The modules that use numpy write::

    if TYPE_CHECKING:
        import numpy as np
    else:
        np = lazy_module('numpy')

and numpy is imported when one of its attributes is first read: by a batch lookup, an
array-valued message field, ``tf2_geometry_msgs``' covariance math, a URDF robot.
"""

from __future__ import annotations

import importlib.util
import sys
from types import ModuleType

__all__ = ['lazy_module']


def lazy_module(name: str) -> ModuleType:
    """
    Return module ``name``, to be imported when one of its attributes is first read.

    An already imported module is returned as it is.

    :raises ModuleNotFoundError: the module is not installed (found out now, not on first use).
    """
    module = sys.modules.get(name)
    if module is not None:
        return module
    spec = importlib.util.find_spec(name)
    if spec is None or spec.loader is None:
        msg = f'No module named {name!r}'
        raise ModuleNotFoundError(msg, name=name)
    loader = importlib.util.LazyLoader(spec.loader)
    spec.loader = loader
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    loader.exec_module(module)
    return module
