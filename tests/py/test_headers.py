"""pulab.profiles.headers (and each profile's ``header``): the C headers compile cleanly with a
real compiler, their include guards work, and every integer the compiler reads from a
``#define`` — casts applied — is the integer the line writes and the report holds."""
import re
import shutil
import subprocess

import pytest

from conftest import SEED_INPUT
from pulab import report
from pulab.profiles import header, registry

NAMES = registry.names()

GCC = shutil.which("gcc")
pytestmark = pytest.mark.skipif(GCC is None, reason="needs gcc")
INTEGER = re.compile(r"^#define\s+(\w+)\s+(?:\(\((u?int\d+_t)\)(-?\d+)\)|(-?\d+))\s*(?:/\*.*)?$")


@pytest.fixture(scope="module")
def rep():
    return report({**SEED_INPUT, "profiles": {}})


@pytest.mark.parametrize("name", NAMES)
def test_header_compiles_and_every_integer_reads_back(name, rep, tmp_path):
    text = header(rep, name)
    (tmp_path / "h.h").write_text(text, encoding="utf-8")
    defines = [(m[1], int(m[3] or m[4])) for m in map(INTEGER.match, text.splitlines()) if m]
    assert len(defines) >= 4, text[:500]
    prog = ['#include "h.h"', '#include "h.h"', "#include <stdio.h>", "int main(void) {"]
    prog += [f'  printf("%lld\\n", (long long)({n}));' for n, _ in defines] + ["  return 0;", "}"]
    (tmp_path / "main.c").write_text("\n".join(prog) + "\n", encoding="utf-8")
    build = subprocess.run([GCC, "-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic", "-o",
                            str(tmp_path / "main"), str(tmp_path / "main.c")],
                           capture_output=True, text=True, timeout=60)
    assert build.returncode == 0, build.stderr
    out = subprocess.run([str(tmp_path / "main")], capture_output=True, text=True, timeout=60)
    assert [int(x) for x in out.stdout.split()] == [v for _, v in defines]


#: ST's parameters_conversion.h computes these from the header's lines (MCSDK's own formulas,
#: its SQRT_2/SQRT_3 literals); the header only names them in comments.
ST_CONVERSION = {
    "CURRENT_CONV_FACTOR": "(uint16_t)((65536.0 * RSHUNT * AMPLIFICATION_GAIN) / ADC_REFERENCE_VOLTAGE)",
    "MAX_VOLTAGE": "(int16_t)((ADC_REFERENCE_VOLTAGE / 1.732051) / VBUS_PARTITIONING_FACTOR)",
    "MAX_BEMF_VOLTAGE": "(uint16_t)((MAX_APPLICATION_SPEED_RPM * 1.2 * MOTOR_VOLTAGE_CONSTANT * 1.4142)"
                        " / (1000u * 1.732051))",
    "C1": "(int32_t)((F1 * RS) / (LS * (PWM_FREQUENCY / REGULATION_EXECUTION_RATE)))",
    "C3": "(int32_t)((F1 * MAX_BEMF_VOLTAGE) / (LS * MAX_CURRENT * (PWM_FREQUENCY / REGULATION_EXECUTION_RATE)))",
    "C5": "(int32_t)((F1 * MAX_VOLTAGE) / (LS * MAX_CURRENT * (PWM_FREQUENCY / REGULATION_EXECUTION_RATE)))",
}


def _run(tmp_path, text: str, body: list) -> list:
    (tmp_path / "h.h").write_text(text, encoding="utf-8")
    prog = ['#include "h.h"', "#include <stdio.h>", "int main(void) {", *body, "  return 0;", "}"]
    (tmp_path / "st.c").write_text("\n".join(prog) + "\n", encoding="utf-8")
    build = subprocess.run([GCC, "-std=c99", "-o", str(tmp_path / "st"), str(tmp_path / "st.c")],
                           capture_output=True, text=True, timeout=60)
    assert build.returncode == 0, build.stderr
    out = subprocess.run([str(tmp_path / "st")], capture_output=True, text=True, timeout=60)
    return [int(x) for x in out.stdout.split()]


@pytest.mark.parametrize("name", [n for n in NAMES if n != "inovance"])
def test_the_profiles_integers_are_what_its_firmware_reads(name, rep, tmp_path):
    """Each integer the report holds is written in the header, or (ST) is what ST's
    parameters_conversion.h computes from the header's lines, compiled by gcc."""
    text = header(rep, name)
    written = {int(m[3] or m[4]) for m in map(INTEGER.match, text.splitlines()) if m}
    stored = {k: c["value"] for k, c in rep["profiles"][name]["constants"].items()
              if isinstance(c["value"], int)}
    derived = {k: v for k, v in stored.items() if k in ST_CONVERSION} if name == "st" else {}
    assert stored and {v for k, v in stored.items() if k not in derived} <= written
    if derived:
        body = ["#define MAX_CURRENT (ADC_REFERENCE_VOLTAGE / (2 * RSHUNT * AMPLIFICATION_GAIN))"]
        body += [f"#define {k} {ST_CONVERSION[k]}" for k in ("MAX_VOLTAGE", "MAX_BEMF_VOLTAGE")]
        body += [f'  printf("%lld\\n", (long long)({ST_CONVERSION[k]}));' for k in derived]
        assert _run(tmp_path, text, body) == list(derived.values())
