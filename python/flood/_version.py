# The project's version: CMakeLists.txt's project(VERSION), pyproject.toml's and `flood
# --version`'s (python/tests/test_inputs.py holds them equal).
__version__ = "0.1"
