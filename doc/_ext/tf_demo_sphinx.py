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
Sphinx extension of tf_demo's site: pages made from the repository's own sources.

- ``repo-include``: a part of a Markdown file of the repository (``README.md``,
  ``bench/README.md``), between two marker lines, parsed as MyST. The text stays in its file.
- one page per executable of ``setup.py``'s ``NODES``, ``TOOLS`` and ``ALIASES``, written into
  ``executables/`` when the build starts: the module's docstring and, for a tool, what its
  ``--help`` prints (its argparse parser, or upstream's usage text where the tool emulates it).
"""

from __future__ import annotations

import ast
import contextlib
import functools
import importlib
import inspect
import io
import os
from pathlib import Path
import sys
from typing import Any
from typing import ClassVar

from docutils import nodes
from docutils.parsers.rst import directives
from docutils.statemachine import StringList
from sphinx import addnodes
from sphinx.application import Sphinx
from sphinx.config import Config
from sphinx.errors import ExtensionError
from sphinx.util.docutils import SphinxDirective

#: argparse wraps help text to the terminal's width: the pages use one width everywhere.
HELP_COLUMNS = '99'
EXECUTABLES_DIR = 'executables'
API_DIR = 'api'
#: Public modules the API reference leaves out, and why.
NOT_IN_API = {
    'tf_demo.cli': 'the tools: their command lines are documented, one page each',
    'tf_demo.nodes': 'the nodes: documented one page each, with their parameters',
    'tf_demo.transport.rclpy_backend': 'imports rclpy: the ROS world behind the facades',
    'tf_demo.transport.rclpy_builders': 'imports rclpy: the ROS world behind the facades',
    'tf_demo.transport.rclpy_serve': 'imports rclpy: the ROS world behind SubscriptionServer',
    'tf_demo.__main__': '`python -m tf_demo` prints the build',
}


def _root(app: Sphinx) -> Path:
    return Path(app.config.tf_demo_root)


class RepoInclude(SphinxDirective):
    """Include the lines of a repository file after ``:start-after:`` up to ``:end-before:``."""

    required_arguments = 1
    option_spec: ClassVar[dict[str, Any]] = {
        'start-after': directives.unchanged_required,
        'end-before': directives.unchanged_required,
    }

    def run(self) -> list[nodes.Node]:
        path = _root(self.env.app) / self.arguments[0]
        self.env.note_dependency(str(path))
        text = path.read_text(encoding='utf-8')
        start = self.options.get('start-after')
        if start is not None:
            if start not in text:
                raise self.error(f'{self.arguments[0]} has no line {start!r}')
            text = text.split(start, 1)[1]
        end = self.options.get('end-before')
        if end is not None:
            if end not in text:
                raise self.error(f'{self.arguments[0]} has no line {end!r} after the start')
            text = text.split(end, 1)[0]
        container = nodes.container()
        lines = StringList(text.splitlines(), source=str(path))
        self.state.nested_parse(lines, 0, container, match_titles=True)
        return container.children


def executables(root: Path) -> tuple[list[str], list[str], dict[str, str]]:
    """``setup.py``'s ``NODES``, ``TOOLS`` and ``ALIASES``, read without running it."""
    found: dict[str, Any] = {}
    for statement in ast.parse((root / 'setup.py').read_text(encoding='utf-8')).body:
        if isinstance(statement, ast.Assign) and len(statement.targets) == 1:
            target = statement.targets[0]
            if isinstance(target, ast.Name) and target.id in ('NODES', 'TOOLS', 'ALIASES'):
                found[target.id] = ast.literal_eval(statement.value)
    return found['NODES'], found['TOOLS'], found['ALIASES']


def help_text(module_name: str) -> str:
    """Return what ``<tool> --help`` prints, from the tool's own ``main``."""
    module = importlib.import_module(module_name)
    out = io.StringIO()
    previous = os.environ.get('COLUMNS')
    os.environ['COLUMNS'] = HELP_COLUMNS
    try:
        with contextlib.redirect_stdout(out), contextlib.suppress(SystemExit):
            module.main(['--help'])
    finally:
        if previous is None:
            del os.environ['COLUMNS']
        else:
            os.environ['COLUMNS'] = previous
    if not out.getvalue().strip():
        raise ExtensionError(f'{module_name}.main(["--help"]) printed nothing')
    return out.getvalue()


def public_modules(root: Path) -> list[str]:
    """Every module of the package not named ``_private`` (nor under one), but ``NOT_IN_API``."""
    found = []
    for path in sorted((root / 'tf_demo').rglob('*.py')):
        parts = path.relative_to(root).with_suffix('').parts
        if parts[-1] == '__init__':
            parts = parts[:-1]
        name = '.'.join(parts)
        if any(part.startswith('_') for part in parts[1:]):
            continue
        if any(name == skip or name.startswith(skip + '.') for skip in NOT_IN_API):
            continue
        found.append(name)
    return sorted(found)


def _api_index(modules: list[str]) -> str:
    lines = [
        'API reference',
        '=============',
        '',
        'Generated from the docstrings and type hints of every public module (not the',
        "executables' modules, documented as :doc:`../executables/index`, nor the rclpy world's",
        'backend, which needs ROS 2 to import). Each name is documented on the page of the module',
        'that defines it (not where it is re-exported).',
        '',
        '.. toctree::',
        '   :maxdepth: 1',
        '',
        *[f'   {name}' for name in modules],
        '',
    ]
    return '\n'.join(lines)


def _api_page(name: str) -> str:
    title = f'``{name}``'
    return '\n'.join([title, '=' * len(title), '', f'.. automodule:: {name}', ''])


class ExecutableHelp(SphinxDirective):
    """The literal ``--help`` output of the tool module named as the argument."""

    required_arguments = 1

    def run(self) -> list[nodes.Node]:
        text = help_text(self.arguments[0])
        block = nodes.literal_block(text, text, language='text')
        return [block]


def _page(name: str, module: str, kind: str) -> str:
    title = f'``{name}``'
    lines = [title, '=' * len(title), '', f'.. automodule:: {module}', '   :no-members:', '']
    if kind == 'tool':
        lines += ['Command line', '------------', '', f'.. tf-executable-help:: {module}', '']
    else:
        lines += [
            'Command line',
            '------------',
            '',
            'A node: it takes no options of its own, only ROS 2 arguments',
            '(``--ros-args -p name:=value --params-file FILE -r from:=to``), in both worlds;',
            'its parameters are the ones above.',
            '',
        ]
    return '\n'.join(lines)


def _index(nodes_: list[str], tools: list[str], aliases: dict[str, str]) -> str:
    alias_lines = [
        f'- ``{alias}``: the same program as :doc:`{tool}`' for alias, tool in aliases.items()
    ]
    lines = [
        'Executables',
        '===========',
        '',
        'One page per executable that ``setup.py`` installs, generated from its module and its',
        'command line when the site is built.',
        '',
        '.. toctree::',
        '   :caption: Nodes',
        '   :maxdepth: 1',
        '',
        *[f'   {name}' for name in nodes_],
        '',
        '.. toctree::',
        '   :caption: Tools',
        '   :maxdepth: 1',
        '',
        *[f'   {name}' for name in tools],
        '',
        "Upstream's names for two of the tools:",
        '',
        *alias_lines,
        '',
    ]
    return '\n'.join(lines)


def write_pages(app: Sphinx, config: Config) -> None:
    """
    Write ``executables/*.rst`` and ``api/index.rst`` (generated, not committed).

    On ``config-inited``: before Sphinx lists the source files and autosummary reads them.
    """
    root = _root(app)
    modules = public_modules(root)
    api_pages = {'index': _api_index(modules)}
    api_pages.update({name: _api_page(name) for name in modules})
    _write_pages(Path(app.srcdir) / API_DIR, api_pages)
    nodes_, tools, aliases = executables(_root(app))
    pages = {'index': _index(nodes_, tools, aliases)}
    pages.update({name: _page(name, f'tf_demo.nodes.{name}', 'node') for name in nodes_})
    pages.update({name: _page(name, f'tf_demo.cli.{name}', 'tool') for name in tools})
    _write_pages(Path(app.srcdir) / EXECUTABLES_DIR, pages)


def _write_pages(folder: Path, pages: dict[str, str]) -> None:
    """Make ``folder`` hold exactly ``pages`` (name: text), touching only changed files."""
    folder.mkdir(exist_ok=True)
    for stale in folder.glob('*.rst'):
        if stale.stem not in pages:
            stale.unlink()
    for name, text in pages.items():
        path = folder / f'{name}.rst'
        if not path.is_file() or path.read_text(encoding='utf-8') != text:
            path.write_text(text, encoding='utf-8')


def _lookup(namespace: object, dotted: str) -> object:
    for part in dotted.split('.'):
        namespace = getattr(namespace, part)
    return namespace


def python_object(module_name: str | None, class_name: str | None, target: str) -> object:
    """Return what ``target`` names where it is written (class, then module), or absolute."""
    scopes: list[object] = []
    if module_name:
        with contextlib.suppress(ImportError):
            module = importlib.import_module(module_name)
            if class_name:
                with contextlib.suppress(AttributeError):
                    scopes.append(_lookup(module, class_name))
            scopes.append(module)
    if module_name:  # a class re-exported from where it is defined: its annotations' scope
        scopes.extend(_defining_modules(module_name))
    for scope in scopes:
        with contextlib.suppress(AttributeError):
            return _lookup(scope, target)
    if module_name:  # imported for type checking only: the name's import statement says it
        head, _, rest = target.partition('.')
        imported = _static_imports(module_name).get(head)
        if imported == '':  # a type alias the module defines for type checking
            return None
        if imported is not None:
            target = f'{imported}.{rest}' if rest else imported
    parts = target.split('.')
    for cut in range(len(parts), 0, -1):
        with contextlib.suppress(ImportError, AttributeError, ValueError):
            return _lookup(importlib.import_module('.'.join(parts[:cut])), '.'.join(parts[cut:]))
    raise LookupError(target)


@functools.cache
def _defining_modules(module_name: str) -> list[object]:
    """
    Return the modules where the classes of ``module_name`` were written (their methods' globals).

    The generated message classes name their module as the package module's, but their
    annotations are written in ``tf_demo.msgs._types``.
    """
    module = importlib.import_module(module_name)
    found: dict[str, object] = {}
    for value in vars(module).values():
        if not inspect.isclass(value):
            continue
        for member in vars(value).values():
            code_globals = getattr(member, '__globals__', None)
            name = code_globals.get('__name__') if isinstance(code_globals, dict) else None
            if isinstance(name, str) and name != module_name and name.startswith('tf_demo.'):
                found[name] = sys.modules[name]
    return [found[name] for name in sorted(found)]


@functools.cache
def _static_imports(module_name: str) -> dict[str, str]:
    """
    Local name -> full name of every ``import`` in a module's source (``TYPE_CHECKING`` too).

    A name the module assigns (a type alias) maps to ``''``.
    """
    try:
        source = inspect.getsource(importlib.import_module(module_name))
    except (ImportError, OSError, TypeError):
        return {}
    names: dict[str, str] = {}
    for node in ast.walk(ast.parse(source)):
        if isinstance(node, ast.Import):
            for alias in node.names:
                if alias.asname:
                    names[alias.asname] = alias.name
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            for alias in node.names:
                names[alias.asname or alias.name] = f'{node.module}.{alias.name}'
        elif isinstance(node, ast.AnnAssign | ast.Assign):
            targets = node.targets if isinstance(node, ast.Assign) else [node.target]
            names.update((target.id, '') for target in targets if isinstance(target, ast.Name))
    return names


def _canonical(value: object) -> str | None:
    """``module.qualname`` of a module, class or function (None for anything else)."""
    if inspect.ismodule(value):
        return value.__name__
    if isinstance(value, property) and value.fget is not None:
        value = value.fget
    if inspect.isclass(value) or inspect.isroutine(value):
        module, qualname = getattr(value, '__module__', None), getattr(value, '__qualname__', '')
        if module and qualname and '<' not in qualname:
            return f'{module}.{qualname}'
    return None


def resolve_python_names(app: Sphinx, doctree: nodes.document) -> None:
    """
    Point each Python reference at the name's definition, as Python resolves the name there.

    ``BufferCore`` in a docstring or an annotation of ``tf_demo.bag`` is the class imported
    there: the reference goes to ``tf_demo.core.buffer_core.BufferCore`` (its page), not to
    whichever object of that short name Sphinx finds first. A type alias, a ``TypeVar`` or a
    name from outside tf_demo (stdlib, numpy) is shown as text: not a page of this site. A name
    Python cannot find is left alone, so that the nitpicky build reports it.
    """
    for ref in list(doctree.findall(addnodes.pending_xref)):
        if ref.get('refdomain') != 'py':
            continue
        target = str(ref['reftarget']).lstrip('.~')
        if '[' in target:  # a subscripted annotation Sphinx could not split: its text
            ref.replace_self(ref.children)
            continue
        try:
            value = python_object(ref.get('py:module'), ref.get('py:class'), target)
        except (LookupError, ImportError):
            continue
        canonical = _canonical(value)
        if canonical is not None and canonical.startswith('tf_demo.'):
            ref['reftarget'] = canonical
            ref['refspecific'] = False
        else:  # an alias, a TypeVar, a constant, or not tf_demo's
            ref.replace_self(ref.children)


def setup(app: Sphinx) -> dict[str, Any]:
    """Register the directives and the executables' pages."""
    app.add_config_value('tf_demo_root', '', 'env', types=[str])
    app.add_directive('repo-include', RepoInclude)
    app.add_directive('tf-executable-help', ExecutableHelp)
    app.connect('config-inited', write_pages)
    app.connect('doctree-read', resolve_python_names)
    return {'version': '1', 'parallel_read_safe': True, 'parallel_write_safe': True}
