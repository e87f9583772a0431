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
C's ``strtod`` and ``strtoll`` as glibc reads them: the prefix rule, and glibc itself as oracle.

The one emulation serves rcl's typing of ``-p`` values and the tools' ``std::stod``/``stof``;
the differential tests call the real ``strtod`` of this process' C library through ctypes and
compare value, length and ``ERANGE``.
"""

from __future__ import annotations

from collections.abc import Callable
import ctypes
import ctypes.util
import math
import platform

from hypothesis import example
from hypothesis import given
from hypothesis import settings
from hypothesis import strategies as st
import pytest
from tf_demo.transport.params_c_numbers import c_strtod
from tf_demo.transport.params_c_numbers import c_strtoll
from tf_demo.transport.params_c_numbers import CDouble
from tf_demo.transport.params_c_numbers import INT64_MAX
from tf_demo.transport.params_c_numbers import INT64_MIN

ERANGE = 34  # Linux


@pytest.mark.parametrize(
    ('text', 'expected'),
    [
        ('1.5', (1.5, 3)),
        ('  -2e3xyz', (-2000.0, 6)),
        ('1.0foo', (1.0, 3)),
        ('.5', (0.5, 2)),
        ('0x1p4', (16.0, 5)),
        ('1e', (1.0, 1)),
        ('abc', None),
        ('', None),
        ('-', None),
    ],
)
def test_c_strtod_takes_the_numeric_prefix(text, expected):
    """The strtod-like parser consumes the longest numeric prefix, as std::stod does."""
    parsed = c_strtod(text)
    assert (parsed if parsed is None else (parsed.value, parsed.length)) == expected


def test_c_strtod_special_values():
    """inf and nan are numbers for strtod."""
    assert c_strtod('-inf') == CDouble(-math.inf, 4, False)
    parsed = c_strtod('nan')
    assert parsed is not None
    assert math.isnan(parsed.value)


@pytest.mark.parametrize(
    ('text', 'value', 'out_of_range'),
    [
        ('1e400', math.inf, True),
        ('-1e400', -math.inf, True),
        ('1e-400', 0.0, True),
        ('0e-400', 0.0, False),
        ('1e-310', 1e-310, True),  # an inexact subnormal: glibc sets ERANGE
        ('0x1p-1074', 5e-324, False),  # an exact subnormal does not
        ('0x' + 'f' * 300, math.inf, True),
    ],
)
def test_c_strtod_says_where_glibc_sets_erange(text, value, out_of_range):
    """Overflow, underflow to zero and inexact subnormals are ERANGE, with glibc's value."""
    assert c_strtod(text) == CDouble(value, len(text), out_of_range)


def test_c_strtoll_reads_whole_int64_only():
    """strtoll base 0 on the whole text: hex, octal, decimal, within int64, else None."""
    assert [c_strtoll(t) for t in ('0x1F', '010', '-0', '+5', '08', '1_000')] == [
        31,
        8,
        0,
        5,
        None,
        None,
    ]
    assert c_strtoll(str(INT64_MAX)) == INT64_MAX
    assert c_strtoll(str(INT64_MIN)) == INT64_MIN
    assert c_strtoll(str(INT64_MAX + 1)) is None
    assert c_strtoll('9' * 5000) is None  # no int conversion of 5,000 digits


@settings(max_examples=150, deadline=None)
@given(st.text(max_size=30))
def test_c_strtod_never_raises(text: str) -> None:
    """strtod's prefix rule on any text: a value and a length, or None."""
    parsed = c_strtod(text)
    if parsed is not None:
        assert 0 < parsed.length <= len(text)


# -- glibc as the oracle ---------------------------------------------------------------------

NUMBER_ALPHABET = st.sampled_from(list('0123456789abcdefxXpPeE+-.infINFtyNA()_ \t\n\v\f\r'))
DECIMALS = st.builds(
    '{}{}e{}'.format,
    st.sampled_from(['', '-', '+', ' ']),
    st.text(alphabet=st.sampled_from(list('0123456789.')), min_size=1, max_size=25),
    st.integers(min_value=-400, max_value=400),
)
HEXES = st.builds(
    '0x{}p{}'.format,
    st.text(alphabet=st.sampled_from(list('0123456789abcdef.')), min_size=1, max_size=20),
    st.integers(min_value=-1200, max_value=1200),
)


def _libc_strtod() -> Callable[..., float]:
    """Return glibc's strtod through ctypes, or skip where the C library is not glibc."""
    if platform.libc_ver()[0] != 'glibc':
        pytest.skip('the oracle is glibc')
    libc = ctypes.CDLL(ctypes.util.find_library('c'), use_errno=True)
    strtod = libc.strtod
    strtod.restype = ctypes.c_double
    strtod.argtypes = [ctypes.c_char_p, ctypes.POINTER(ctypes.c_char_p)]
    return strtod


def _glibc(text: str) -> CDouble | None:
    strtod = _libc_strtod()
    data = ctypes.create_string_buffer(text.encode('ascii'))
    end = ctypes.c_char_p()
    ctypes.set_errno(0)
    value = strtod(data, ctypes.byref(end))
    errno = ctypes.get_errno()
    end_address = ctypes.cast(end, ctypes.c_void_p).value
    assert end_address is not None  # strtod always sets the end pointer
    length = end_address - ctypes.addressof(data)
    if length == 0:
        return None
    return CDouble(value, length, errno == ERANGE)


def _same(ours: CDouble | None, theirs: CDouble | None) -> bool:
    if ours is None or theirs is None:
        return ours is theirs
    if math.isnan(ours.value) or math.isnan(theirs.value):
        both_nan = math.isnan(ours.value) and math.isnan(theirs.value)
        return both_nan and ours[1:] == theirs[1:]
    return ours == theirs and math.copysign(1, ours.value) == math.copysign(1, theirs.value)


@pytest.mark.differential
@settings(max_examples=300, deadline=None)
@given(st.text(alphabet=NUMBER_ALPHABET, max_size=30) | DECIMALS | HEXES)
@example('1e-310')
@example('4.9e-324')
@example('2.4703282292062328e-324')  # just above half the smallest subnormal
@example('0x1.fffffffffffff8p1023')  # rounds up to 2**1024: overflow
@example('0x1p-1075')
@example('0x1.8p-1075')
@example('1.7976931348623158e308')
@example('-nan(abc)x')
@example('infinit')
def test_c_strtod_agrees_with_glibc(text: str) -> None:
    """Value, characters read and ERANGE are glibc's, for number-like text of every kind."""
    ours, theirs = c_strtod(text), _glibc(text)
    assert _same(ours, theirs), (text, ours, theirs)
