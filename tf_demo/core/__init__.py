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

"""tf2's buffer in pure Python (stdlib + numpy): math, caches, ``BufferCore``, exceptions."""

from tf_demo.core.buffer_core import BufferCore
from tf_demo.core.buffer_core import MAX_GRAPH_DEPTH
from tf_demo.core.buffer_core import TransformResult
from tf_demo.core.exceptions import BackwardExtrapolationException
from tf_demo.core.exceptions import ConnectivityException
from tf_demo.core.exceptions import ExtrapolationException
from tf_demo.core.exceptions import ForwardExtrapolationException
from tf_demo.core.exceptions import InvalidArgumentException
from tf_demo.core.exceptions import LookupException
from tf_demo.core.exceptions import NoDataForExtrapolationException
from tf_demo.core.exceptions import TimeoutException
from tf_demo.core.exceptions import TransformException
from tf_demo.core.frames_format import FrameInfo
from tf_demo.core.time_cache import DEFAULT_CACHE_TIME_NS
from tf_demo.core.time_cache import display_time_point
from tf_demo.core.time_cache import StaticCache
from tf_demo.core.time_cache import TimeCache

__all__ = [
    'DEFAULT_CACHE_TIME_NS',
    'MAX_GRAPH_DEPTH',
    'BackwardExtrapolationException',
    'BufferCore',
    'ConnectivityException',
    'ExtrapolationException',
    'ForwardExtrapolationException',
    'FrameInfo',
    'InvalidArgumentException',
    'LookupException',
    'NoDataForExtrapolationException',
    'StaticCache',
    'TimeCache',
    'TimeoutException',
    'TransformException',
    'TransformResult',
    'display_time_point',
]
