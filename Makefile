# ocioforge: `make run` builds everything from a fresh clone; `make test` runs the suite.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin
STAMP := $(VENV)/.installed-stamp
CONFIG := configs/ocioforge-studio

.PHONY: run test bench clean

# compileall: the package's bytecode, as a wheel's install writes it; where Python writes none
# (PYTHONDONTWRITEBYTECODE), every command compiled it anew, 0.3 s of each start.
$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -e '.[test,dask]'
	$(BIN)/python -m compileall -q generator
	touch $(STAMP)

run: $(STAMP)
	$(BIN)/python -m compileall -q generator
	$(BIN)/ocioforge build -o $(CONFIG) --force
	$(BIN)/ocioforge pack -o luts
	$(BIN)/ocioforge verify $(CONFIG)/config.ocio --summary --report build/verify --force

test: $(STAMP)
	$(BIN)/ruff check generator tests bench
	$(BIN)/ruff format --check --quiet generator tests bench
	$(BIN)/mypy generator
	$(BIN)/pytest -n 2 -p no:warnings

bench: $(STAMP)
	$(BIN)/python -m compileall -q generator
	$(BIN)/python bench/build.py
	$(BIN)/python bench/verify.py
	$(BIN)/python bench/lut_accuracy.py
	$(BIN)/python bench/lut_bake.py
	$(BIN)/python bench/aces_views.py
	$(BIN)/python bench/aces_inverse.py
	$(BIN)/python bench/convert.py
	$(BIN)/python bench/pack.py

clean:
	rm -rf $(VENV) .pytest_cache
