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
ros.geometry's rotation helpers follow tf2_geometry_msgs' arithmetic; pinned here to math3d.

math3d is the one source of the rotation math.  :mod:`tf_demo.ros.geometry` keeps upstream
Python's own formulas (its quaternion to matrix, Bar-Itzhack's matrix to quaternion) so that
``do_transform_*`` match tf2_geometry_msgs to the last bit; these tests pin them to
:func:`math3d.matrix_from_quat` and :func:`math3d.quat_from_matrix` within 1e-12.
"""

from __future__ import annotations

from hypothesis import given
import numpy as np
import pytest
from tf_demo.core import math3d
from tf_demo.ros import geometry
from tf_demo.testing import strategies as tfst

pytestmark = pytest.mark.property

TOL = 1e-12


@given(tfst.raw_quaternions())
@tfst.profile_settings(200)
def test_matrix_from_quaternion_is_math3d(q: math3d.Quat) -> None:
    """``geometry._matrix_from_quat_wxyz`` (divides by the squared norm) is math3d's matrix."""
    x, y, z, w = q
    expected = np.array(math3d.matrix_from_quat(q))
    assert np.allclose(geometry._matrix_from_quat_wxyz(w, x, y, z), expected, rtol=0.0, atol=TOL)


@given(tfst.unit_quaternions())
@tfst.profile_settings(200)
def test_bar_itzhack_quaternion_is_math3d_up_to_sign(q: math3d.Quat) -> None:
    """``geometry._quat_wxyz_from_matrix`` of a rotation matrix is math3d's, up to sign."""
    matrix = np.array(math3d.matrix_from_quat(q))
    w, x, y, z = geometry._quat_wxyz_from_matrix(matrix).tolist()
    expected = np.array(math3d.quat_from_matrix(math3d.matrix_from_quat(q)))
    got = np.array([x, y, z, w])
    assert np.allclose(got, expected, rtol=0.0, atol=TOL) or np.allclose(
        got, -expected, rtol=0.0, atol=TOL
    )
