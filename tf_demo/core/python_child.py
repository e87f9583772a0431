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
Child Python processes that import the installed tf_demo whatever the working directory holds.

``python -c`` puts the working directory first on ``sys.path``; a folder named ``tf_demo``
there (the clone of this repository, in the course's ``~/tf_demo``) is then imported as a
namespace package in place of an installed one found through a finder (an editable install),
and ``tf_demo.urdf`` becomes its folder of robot files. Every child we start drops that entry
before it imports anything, as ``-P`` (Python 3.11+) would, on every supported Python.
"""

from __future__ import annotations

import sys

__all__ = ['WITHOUT_WORKING_DIRECTORY', 'python_child_command']

#: The first statement of a child's ``-c`` code: the working directory leaves ``sys.path``.
WITHOUT_WORKING_DIRECTORY = "import sys; sys.path[:] = [p for p in sys.path if p != '']\n"


def python_child_command(code: str, *args: str) -> list[str]:
    """Command line running ``code`` in this interpreter, the working directory off its path."""
    return [sys.executable or 'python3', '-c', WITHOUT_WORKING_DIRECTORY + code, *args]
