# Entry points for a fresh machine with Python 3.11, pip and make (README, "Set-up"):
#   make demo   a quick reproduction of the paper
#   make test   ruff, mypy, import-linter and every test (installs Debian's Chromium if missing)
#   make docs   the documentation site in site/, built with mkdocs --strict
#   make lock   re-lock requirements.lock after a change to the dependencies in pyproject.toml
# Each creates the virtual environment (.venv) on first use, from requirements.lock: exact
# versions with their hashes, for every platform, so every machine installs the same. uv
# installs it (the one on PATH, or one that pip fetches into .tools/ from PyPI); with UV=none,
# or if uv cannot be had, pip installs the same lock.
PYTHON ?= python3
VENV ?= .venv
BIN := $(VENV)/bin
TOOLS := .tools
UV ?= $(shell command -v uv 2>/dev/null || echo $(TOOLS)/bin/uv)
UV_VERSION := uv>=0.9,<1
LOCK := requirements.lock
EXTRAS := --extra dev --extra docs
BROWSER := /usr/bin/chromium /usr/bin/chromedriver
export UV_PYTHON_DOWNLOADS := never

.PHONY: demo test lint browser docs lock bench clean

$(BIN)/sarlink: pyproject.toml $(LOCK)
	@if [ "$(UV)" != none ] && { [ -x "$(UV)" ] || \
	        $(PYTHON) -m pip install --quiet --root-user-action=ignore --target $(TOOLS) "$(UV_VERSION)"; }; then \
	    echo "installing $(LOCK) into $(VENV) with uv"; \
	    $(UV) venv --quiet --clear --python $(PYTHON) $(VENV) && \
	    $(UV) pip sync --quiet --python $(BIN)/python $(LOCK) && \
	    $(UV) pip install --quiet --python $(BIN)/python --no-deps -e . ; \
	else \
	    echo "installing $(LOCK) into $(VENV) with pip (no uv)"; \
	    $(PYTHON) -m venv --clear $(VENV) && \
	    $(BIN)/python -m pip install --quiet --require-hashes -r $(LOCK) && \
	    $(BIN)/python -m pip install --quiet --no-deps -e . ; \
	fi
	touch $@

demo: $(BIN)/sarlink
	$(BIN)/sarlink reproduce --quick --figures 1,2,3,4,5,6,7 --out reproduction

# The replay's browser tests drive Debian's Chromium and its driver, never a downloaded build.
browser:
	@missing=$$(for b in $(BROWSER); do [ -x "$$b" ] || printf ' %s' "$$b"; done); \
	if [ -n "$$missing" ]; then \
	    if [ "$$(id -u)" = 0 ] && command -v apt-get >/dev/null; then \
	        echo "installing Debian's chromium and chromium-driver (missing:$$missing)"; \
	        apt-get update -qq && \
	        DEBIAN_FRONTEND=noninteractive apt-get install -y -qq chromium chromium-driver; \
	    else \
	        echo "error: the browser tests need$$missing; install them with" \
	             "'sudo apt-get install -y chromium chromium-driver', then run make test again" >&2; \
	        exit 1; \
	    fi; \
	fi

lint: $(BIN)/sarlink
	$(BIN)/ruff check src tests benchmarks examples docs/hooks.py
	$(BIN)/mypy
	$(BIN)/lint-imports --no-logo

# The browser's download and the linters' CPU overlap; then every test.
test: $(BIN)/sarlink
	@$(MAKE) --no-print-directory -j2 browser lint
	$(BIN)/pytest -q -n auto --dist loadfile

docs: $(BIN)/sarlink
	NO_MKDOCS_2_WARNING=1 $(BIN)/mkdocs build --strict --site-dir site

# One command re-locks after a dependency changed in pyproject.toml (commit requirements.lock).
lock:
	@[ -x "$(UV)" ] || $(PYTHON) -m pip install --quiet --root-user-action=ignore --target $(TOOLS) "$(UV_VERSION)"
	$(UV) pip compile pyproject.toml $(EXTRAS) --universal --python-version 3.11 \
	    --generate-hashes --quiet -o $(LOCK)

bench: $(BIN)/sarlink
	$(BIN)/python benchmarks/bench_engine.py --out benchmarks/results/engine.md
	$(BIN)/python benchmarks/bench_mtsp.py --seeds 5 --busy --out benchmarks/results/mtsp.md
	$(BIN)/python benchmarks/bench_sweep.py --out benchmarks/results/sweep.md

clean:
	rm -rf $(VENV) $(TOOLS) site .pytest_cache .mypy_cache .ruff_cache .hypothesis .import_linter_cache
