# The two entry points. Each installs what is missing (Debian packages), configures, builds,
# then runs. `make demo`: the paper's study into results/. `make test`: every test.
PRESET ?= release
BUILD  := build/$(PRESET)
PYTHON := /usr/bin/python3

.PHONY: all deps configure build demo test clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@test -f $(BUILD)/build.ninja || cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build $(BUILD)

demo: build
	@$(PYTHON) scripts/paper_demo.py --cli $(BUILD)/deploydyn --out results/paper

test: build
	@ctest --preset $(PRESET) -j2

clean:
	rm -rf build results
