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
Sphinx configuration of tf_demo's documentation site (``python -m sphinx -W -n doc OUT``).

rosdoc2 (docs.ros.org) copies this folder (``rosdoc2.yaml``: ``sphinx_sourcedir: doc``) and
executes this file inside its own ``conf.py``: so nothing here may rely on the folder's place in
the repository. The package root is found by ``package.xml``, beside this folder or, in
rosdoc2's copy, beside the ``tf_demo`` package rosdoc2 puts on ``sys.path``.
"""

import doctest
import os
from pathlib import Path
import sys

_here = Path(os.path.abspath(globals().get('__file__', 'conf.py'))).parent
sys.path.insert(0, str(_here / '_ext'))
if (_here.parent / 'package.xml').is_file():
    sys.path.insert(0, str(_here.parent))  # the sources, not an older installed copy
# The API pages are read from the sources: a compiled module (mypyc) has no type hints.
os.environ.setdefault('TF_DEMO_INTERPRETED', '1')
# They document the standalone world (rosdoc2 mocks rclpy: it must not be taken for the real one).
os.environ.setdefault('TF_DEMO_BACKEND', 'dds')
import tf_demo  # noqa: E402

tf_demo_root = str(Path(tf_demo.__file__).resolve().parent.parent)

project = 'tf_demo'
author = 'The tf_demo Authors'
copyright = '2026, The tf_demo Authors. Apache-2.0'
release = version = '0.1.0'

extensions = [
    'sphinx.ext.autodoc',
    'sphinx.ext.doctest',
    'sphinx.ext.viewcode',
    'myst_parser',
    'tf_demo_sphinx',
]
# rosdoc2 writes its own index.rst beside index.md (the root here): it is left out.
exclude_patterns = ['_build', 'license_header.txt', 'index.rst']
myst_heading_anchors = 3
html_theme = 'furo'
html_theme_options: dict[str, object] = {}  # not rosdoc2's (sphinx_rtd_theme's)
html_title = 'tf_demo'

# tf2's messages end with a space ("does not exist. "): compare text, not trailing blanks.
doctest_default_flags = (
    doctest.ELLIPSIS | doctest.IGNORE_EXCEPTION_DETAIL | doctest.NORMALIZE_WHITESPACE
)

# a module documents what it defines; a name it imports is documented where it is defined
autodoc_default_options = {'members': True, 'show-inheritance': True, 'ignore-module-all': True}
autodoc_member_order = 'bysource'
autodoc_typehints = 'signature'
autodoc_typehints_format = 'short'
# Types of the world outside tf_demo that signatures name (no intersphinx: the build is offline).
nitpick_ignore_regex = [
    ('py:class', r'(numpy|numpy\.typing|NDArray)(\..*)?'),
    ('py:class', r'(pathlib|os|types|importlib\.util)\.[A-Za-z]+'),
    # tf_demo's private modules and members (``_name``) are not in the API pages by design.
    ('py:.*', r'(tf_demo\.(\w+\.)*)?_\w+(\.\w+)*'),
]

# rosdoc2: keep this theme and the extensions above (it allows only its own list otherwise);
# tf_demo builds its own API pages, so rosdoc2.yaml turns sphinx-apidoc off.
rosdoc2_settings = {'override_theme': False, 'allow_other_extensions': True}
