import pytest

from foamcase import foam_environment


@pytest.fixture(scope="session")
def foam_env():
    return foam_environment()
