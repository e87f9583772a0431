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
C's ``strtoll`` (base 0) and ``strtod``, read as glibc reads them in the C locale.

The package's one emulation of C number parsing: rcl types ``-p`` values and params-file scalars
with them (:mod:`tf_demo.transport.params_typing`), and the tf tools read their numbers as
``std::stod``/``std::stof`` do (:mod:`tf_demo.cli._args`). :func:`c_strtod` takes the longest
numeric prefix and says whether glibc would set ``ERANGE`` (overflow, underflow to zero, or an
inexact subnormal). The patterns have no ambiguous repetition, so they run in linear time on a
5,000-digit argument.
"""

from __future__ import annotations

import decimal
import math
import re
import sys
from typing import NamedTuple

__all__ = ['INT64_MAX', 'INT64_MIN', 'CDouble', 'c_strtod', 'c_strtoll']

INT64_MIN = -(2**63)
INT64_MAX = 2**63 - 1

_C_SPACE = r'[ \t\n\v\f\r]*'  # isspace() in the C locale; strtod and strtoll skip it
_C_INT = re.compile(rf'{_C_SPACE}([+-]?)(?:0[xX]([0-9a-fA-F]+)|0([0-7]*)|([1-9][0-9]*))')
_C_DOUBLE = re.compile(
    rf"""{_C_SPACE}(?P<sign>[+-]?)(?:
        (?P<hex>0[xX](?=\.?[0-9a-fA-F])[0-9a-fA-F]*(?:\.[0-9a-fA-F]*)?(?:[pP][+-]?[0-9]+)?)
      | (?P<dec>(?=\.?[0-9])[0-9]*(?:\.[0-9]*)?(?:[eE][+-]?[0-9]+)?)
      | (?P<inf>(?i:inf(?:inity)?))
      | (?P<nan>(?i:nan)(?:\([0-9A-Za-z_]*\))?)
    )""",
    re.VERBOSE,
)
# Digits beyond which an int64 has certainly overflowed (leading zeros stripped).
_INT64_DIGITS = {16: 16, 8: 22, 10: 19}


class CDouble(NamedTuple):
    """What ``strtod`` read: the value, how many characters it took, whether errno is ERANGE."""

    value: float
    length: int
    out_of_range: bool


def c_strtoll(text: str) -> int | None:
    """Return ``strtoll(text, &end, 0)`` when it reads all of ``text`` in int64, else None."""
    match = _C_INT.fullmatch(text)
    if match is None:
        return None
    sign, hex_digits, octal_digits, decimal_digits = match.groups()
    base, digits = (
        (16, hex_digits)
        if hex_digits is not None
        else (8, octal_digits)
        if octal_digits is not None
        else (10, decimal_digits)
    )
    digits = digits.lstrip('0')
    if len(digits) > _INT64_DIGITS[base]:
        return None  # ERANGE: rcl then tries the text as a double
    magnitude = int(digits, base) if digits else 0
    value = -magnitude if sign == '-' else magnitude
    return value if INT64_MIN <= value <= INT64_MAX else None


def c_strtod(text: str) -> CDouble | None:
    """
    Read the longest numeric prefix of ``text`` as ``strtod`` does; None when none starts it.

    Leading C white space is skipped (and counted in ``length``); hex floats, ``inf``,
    ``infinity`` and ``nan(...)`` are numbers. Out of range, the value is glibc's: a signed
    infinity for an overflow, zero for an underflow, the rounded subnormal when inexact.
    """
    match = _C_DOUBLE.match(text)
    if match is None:
        return None
    value, out_of_range = (
        (math.inf, False)
        if match['inf'] is not None
        else (math.nan, False)
        if match['nan'] is not None
        else _hex_double(match['hex'][2:])
        if match['hex'] is not None
        else _decimal_double(match['dec'])
    )
    return CDouble(-value if match['sign'] == '-' else value, match.end(), out_of_range)


def _decimal_double(body: str) -> tuple[float, bool]:
    """Read a decimal ``strtod`` body: (value, ERANGE) as glibc (overflow, inexact tiny)."""
    value = float(body)
    if math.isinf(value):
        return value, True
    mantissa = body.partition('e')[0].partition('E')[0]
    if value == 0.0:
        return value, bool(mantissa.strip('0.'))
    if value < sys.float_info.min:  # subnormal: glibc reports ERANGE unless it is exact
        try:
            exact = decimal.Decimal(body) == decimal.Decimal(value)
        except (decimal.DecimalException, ValueError):
            return value, True
        return value, not exact
    return value, False


def _hex_double(body: str) -> tuple[float, bool]:
    """Read a hexadecimal ``strtod`` body (after ``0x``): (value, ERANGE) as glibc."""
    mantissa_text, _, exponent_text = body.lower().partition('p')
    whole, _, fraction = mantissa_text.partition('.')
    mantissa = int((whole + fraction).lstrip('0') or '0', 16)
    if mantissa == 0:
        return 0.0, False
    if len(exponent_text.lstrip('+-').lstrip('0')) > 6:
        # An exponent beyond a million overflows or underflows whatever the mantissa.
        return (0.0 if exponent_text.startswith('-') else math.inf), True
    lowest = int(exponent_text or '0') - 4 * len(fraction)  # the exponent of mantissa's bit 0
    trailing_zeros = (mantissa & -mantissa).bit_length() - 1
    top = lowest + mantissa.bit_length() - 1
    if top >= 1024:
        return math.inf, True
    if top < -1075:
        return 0.0, True
    try:
        value = float.fromhex(f'{whole or "0"}.{fraction}p{int(exponent_text or "0")}')
    except OverflowError:
        return math.inf, True
    return value, value < sys.float_info.min and lowest + trailing_zeros < -1074
