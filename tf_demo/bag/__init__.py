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
Recorded TF: /tf and /tf_static from rosbag2 recordings (MCAP or SQLite3), without ROS.

:func:`open_tf_bag` streams a bag's TF messages in recording order (rosbags reads the container,
this package's CDR decoder the payloads); :func:`load_buffer` fills a
:class:`~tf_demo.core.BufferCore` from one, and :func:`load_bag` also keeps what precedes damage.
Needs the ``bag`` extra (``pip install '.[bag]'``).
"""

from tf_demo.bag.reader import BagError
from tf_demo.bag.reader import BagRecord
from tf_demo.bag.reader import load_bag
from tf_demo.bag.reader import load_buffer
from tf_demo.bag.reader import LoadedBag
from tf_demo.bag.reader import open_tf_bag
from tf_demo.bag.reader import TfBag
from tf_demo.bag.writer import TfBagWriter

__all__ = [
    'BagError',
    'BagRecord',
    'LoadedBag',
    'TfBag',
    'TfBagWriter',
    'load_bag',
    'load_buffer',
    'open_tf_bag',
]
