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
tf2's exception tree, with subclasses telling the three kinds of extrapolation apart.

The names are tf2_py's.  tf2_py raises a plain :class:`ExtrapolationException` for every kind of
extrapolation; here the exception raised is one of its subclasses, so ``except
ExtrapolationException`` keeps working while callers that care can tell past from future.
"""

from __future__ import annotations

__all__ = [
    'BackwardExtrapolationException',
    'ConnectivityException',
    'ExtrapolationException',
    'ForwardExtrapolationException',
    'InvalidArgumentException',
    'LookupException',
    'NoDataForExtrapolationException',
    'TimeoutException',
    'TransformException',
]


class TransformException(Exception):  # noqa: N818 (tf2's names)
    """Base class of every tf2 error."""


class LookupException(TransformException):
    """A frame does not exist, or the tree contains a loop."""


class ConnectivityException(TransformException):
    """The two frames are not part of the same tree."""


class ExtrapolationException(TransformException):
    """The requested time is outside the data held for a link of the path."""


class BackwardExtrapolationException(ExtrapolationException):
    """The requested time is older than the oldest data of a link."""


class ForwardExtrapolationException(ExtrapolationException):
    """The requested time is newer than the newest data of a link."""


class NoDataForExtrapolationException(ExtrapolationException):
    """A link holds no data, or a single sample at a different time."""


class InvalidArgumentException(TransformException):
    """A frame id argument is empty or starts with a slash."""


class TimeoutException(TransformException):
    """A wait for a transform ran out of time."""
