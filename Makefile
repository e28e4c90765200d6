# Two entry points for a fresh machine with Python 3.11 and pip: `make demo` (a quick
# reproduction of the paper) and `make test`.
# Each creates the virtual environment it needs (.venv) on first use.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin

.PHONY: demo test lint bench clean

$(BIN)/sarlink: pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e ".[dev]"
	touch $@

demo: $(BIN)/sarlink
	$(BIN)/sarlink reproduce --quick --out reproduction

lint: $(BIN)/sarlink
	$(BIN)/ruff check src tests benchmarks
	$(BIN)/mypy

test: lint
	$(BIN)/pytest -q

bench: $(BIN)/sarlink
	$(BIN)/python benchmarks/bench_engine.py --out benchmarks/results/engine.md
	$(BIN)/python benchmarks/bench_mtsp.py --out benchmarks/results/mtsp.md
	$(BIN)/python benchmarks/bench_sweep.py --out benchmarks/results/sweep.md

clean:
	rm -rf $(VENV) .pytest_cache .mypy_cache .ruff_cache .hypothesis
