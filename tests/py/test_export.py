"""pulab.export: CSV exports name each column's unit."""
import pytest

from conftest import SEED_INPUT
from pulab import report
from pulab.export import sim_csv


@pytest.mark.parametrize("which, header", [
    ("current", "t_s,si.id_A,si.iq_A,si.ud_V,si.uq_V,pu.id_A"),
    ("pll", "t_s,si.theta_rad,si.theta_hat_rad,si.omega_hat_rad_per_s,pu.theta_rad"),
])
def test_csv_header_has_units(which, header):
    r = report({**SEED_INPUT, "sim": {which: {"duration_s": 0.01}}})
    assert sim_csv(r, which).splitlines()[0].startswith(header)
