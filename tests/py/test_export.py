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


def test_current_csv_has_every_firmwares_run():
    # TI, NXP, ST and Microchip follow the three variants, each column the report's series.
    r = report({**SEED_INPUT, "sim": {"current": {"duration_s": 0.01}}})
    lines = sim_csv(r, "current").splitlines()
    names = lines[0].split(",")
    assert names[13:] == [f"{v}.{s}_{u}" for v in ("ti", "nxp", "st", "microchip")
                          for s, u in (("id", "A"), ("iq", "A"), ("ud", "V"), ("uq", "V"))]
    col = names.index("st.iq_A")
    assert [float(x.split(",")[col]) for x in lines[1:]] == \
        r["sim"]["current"]["by_profile"]["st"]["variant"]["iq"]
