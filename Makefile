# make book : execute every notebook at the paper's parameters, render the book into _build/html
# make test : pytest over tests/ and nbval over notebooks/
# make pdf  : the PDF edition, from the stored notebooks, into _build/latex (Debian's TeX Live)
# Each creates .venv from requirements.txt when it is missing; they need only python3 and make
# (make pdf also Debian's TeX Live, which it names when missing).

PYTHON ?= python3
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed

.PHONY: book test pdf run clean

$(STAMP): requirements.txt pyproject.toml
	@test -x $(BIN)/python || $(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --disable-pip-version-check -r requirements.txt
	$(BIN)/python -m pip install --quiet --disable-pip-version-check --no-deps --no-build-isolation -e .
	@touch $(STAMP)

# JOBS: notebooks executed side by side (default: every core available), e.g. make book JOBS=1
book: $(STAMP)
	$(BIN)/python -m obslib.run --in-place $(if $(JOBS),--jobs $(JOBS))
	$(BIN)/python -m obsbook.report --profile paper --write book/report.md --front book/_front.md
	$(BIN)/python -m obsbook.front --figure book/_static/front.png
	$(BIN)/jupyter-book build . --builder html --warningiserror --nitpick --keep-going

test: $(STAMP)
	$(BIN)/python -m pytest

# The notebooks as stored (no re-execution) through Jupyter Book's LaTeX builder and XeLaTeX;
# says which Debian packages to install when TeX is missing (obsbook/pdf.py).
pdf: $(STAMP)
	$(BIN)/python -m obsbook.pdf

# Rerun notebooks with other parameters into _build/runs/, e.g.
#   make run ARGS="--profile quick"      or      make run ARGS="-p n_scenes 500 01"
run: $(STAMP)
	$(BIN)/python -m obslib.run $(ARGS)

clean:
	rm -rf _build
