"""Helpers of the validation scripts that carry physics: the conversion of
drag correlations for random arrays of spheres to the DLM paper's Lambda."""

import pathlib
import sys

import pytest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "validation"))
from common import (beetstra_drag, correlation_lambda, ergun_lambda,  # noqa: E402
                    tang_drag)


@pytest.mark.parametrize("porosity", [0.36, 0.3983, 0.48])
@pytest.mark.parametrize("re_number", [0.1, 18, 900])
def test_correlations_convert_to_the_papers_lambda(porosity, re_number):
    """Carman-Kozeny's drag law gives Lambda = 180 and Ergun's gives 150 +
    1.75 Re at any porosity, as eq. 25 defines them; the two fits to fully
    resolved simulations reduce to Carman-Kozeny (plus their small Stokes
    correction) as Re goes to 0, and give the values quoted in
    validation/README.md for the paper's bed."""
    def carman_kozeny(phi, re_s):
        return 10*phi/(1 - phi)**2

    def ergun(phi, re_s):
        return (150*phi + 1.75*re_s)/(18*(1 - phi)**2)

    assert correlation_lambda(carman_kozeny, porosity, re_number) == pytest.approx(180)
    assert correlation_lambda(ergun, porosity, re_number) == \
        pytest.approx(ergun_lambda(re_number))
    for drag in (beetstra_drag, tang_drag):
        assert correlation_lambda(drag, porosity, 1e-6) == pytest.approx(180, rel=0.03)


def test_correlations_for_the_papers_random_bed():
    """The paper's bed (porosity 0.3983, Re 897.5 by it): Beetstra et al.
    1348 and Tang et al. 767, against Ergun's 1721."""
    assert correlation_lambda(beetstra_drag, 0.3983, 897.49) == pytest.approx(1348, abs=1)
    assert correlation_lambda(tang_drag, 0.3983, 897.49) == pytest.approx(767, abs=1)
    assert ergun_lambda(897.49) == pytest.approx(1721, abs=1)
