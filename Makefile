# The two entry points. Each installs what is missing (Debian packages), configures, builds,
# then runs. `make demo`: the paper's study, the scissor structures and the mast into results/. `make test`: every test.
# CI also runs `make sanitize` (the tests under ASan + UBSan) and `make fuzz` (60 s of libFuzzer,
# shared by its two targets, built in the sanitizer's build).
PRESET ?= release
BUILD  := build/$(PRESET)
PYTHON := /usr/bin/python3
SHELL  := /bin/bash
FUZZ_SECONDS ?= 60

.PHONY: all deps configure build demo test bench sanitize fuzz verification clean

all: build

deps:
	@scripts/install-deps.sh

configure: deps
	@test -f $(BUILD)/build.ninja || cmake --preset $(PRESET) >/dev/null

build: configure
	@cmake --build $(BUILD)

# The paper's study, then the scissor arch and ring and the spring-driven mast (docs/boom.md) at
# the same three ΔT; each runs even if another fails.
demo: build
	@status=0; \
	$(PYTHON) scripts/paper_demo.py --cli $(BUILD)/deploydyn --out results/paper || status=1; \
	$(PYTHON) scripts/scissor_demo.py --cli $(BUILD)/deploydyn --out results/scissor || status=1; \
	$(PYTHON) scripts/boom_demo.py --cli $(BUILD)/deploydyn --out results/boom || status=1; \
	$(PYTHON) scripts/checks_demo.py --cli $(BUILD)/deploydyn --out results/checks || status=1; \
	$(PYTHON) scripts/thermal_demo.py --cli $(BUILD)/deploydyn --out results/thermal || status=1; \
	exit $$status

test: build
	@ctest --preset $(PRESET) -j2

# Speed and memory (bench/, Google Benchmark): medians of BENCH_REPETITIONS runs as a table.
BENCH_REPETITIONS ?= 3
bench: build
	@cmake --build $(BUILD) --target deploydyn_bench
	@$(PYTHON) scripts/bench_table.py --binary $(BUILD)/bench/deploydyn_bench --repetitions $(BENCH_REPETITIONS)

# The whole test suite built with clang's AddressSanitizer and UndefinedBehaviorSanitizer, and in
# the same build the libFuzzer targets (one compilation of the library serves both). It compiles
# at -O1 -g1 (line tables: file and line in every report), which halves its build time against
# -O2 -g. The asan test preset leaves out the convergence-order studies, the slender-column study,
# three long 3D beam verifications, the cross-checks of the paper's runs against the independent
# solution, the two-domain solve's long refactorization series and the CFRP boom's latching
# (about 320 s of the sanitizer's run): they repeat, over many more steps, code that other tests
# run under it.
SANITIZE_BUILD := build/asan
sanitize: deps
	@test -f $(SANITIZE_BUILD)/build.ninja || cmake --preset asan >/dev/null
	@cmake --build $(SANITIZE_BUILD)
	@ctest --preset asan -j2

# Bounded libFuzzer runs, FUZZ_SECONDS in all: two thirds for the model loader, seeded with the
# examples and the bad models, one third for study files (fuzz/study_loader_fuzzer.cpp), seeded
# with the examples' studies and fuzz/seeds/study. Each prints its executions.
FUZZ_STUDY_SECONDS = $(shell echo $$(( $(FUZZ_SECONDS) / 3 )))
FUZZ_MODEL_SECONDS = $(shell echo $$(( $(FUZZ_SECONDS) - $(FUZZ_SECONDS) / 3 )))
FUZZ_STATS := grep -E '^(stat::number_of_executed_units|stat::average_exec_per_sec|==|SUMMARY|Done)'
fuzz: deps
	@test -f $(SANITIZE_BUILD)/build.ninja || cmake --preset asan >/dev/null
	@cmake --build $(SANITIZE_BUILD) --target model_loader_fuzzer study_loader_fuzzer
	@rm -rf $(SANITIZE_BUILD)/corpus $(SANITIZE_BUILD)/study_corpus && mkdir -p $(SANITIZE_BUILD)/corpus $(SANITIZE_BUILD)/study_corpus
	@cp examples/paper/*.yaml examples/beams/*.yaml examples/petal/*.yaml examples/cables/*.yaml examples/boom/*.yaml examples/tutorial/*.yaml tests/io/bad_models/*.yaml fuzz/seeds/*.json $(SANITIZE_BUILD)/corpus/
	@cp examples/*/*_study.yaml fuzz/seeds/study/* $(SANITIZE_BUILD)/study_corpus/
	@$(SANITIZE_BUILD)/model_loader_fuzzer $(SANITIZE_BUILD)/corpus -dict=fuzz/model.dict -max_len=4096 \
	  -max_total_time=$(FUZZ_MODEL_SECONDS) -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 2>&1 \
	  | $(FUZZ_STATS) ; test $${PIPESTATUS[0]} -eq 0
	@$(SANITIZE_BUILD)/study_loader_fuzzer $(SANITIZE_BUILD)/study_corpus -dict=fuzz/study.dict -max_len=4096 \
	  -max_total_time=$(FUZZ_STUDY_SECONDS) -timeout=10 -rss_limit_mb=4096 -print_final_stats=1 2>&1 \
	  | $(FUZZ_STATS) ; test $${PIPESTATUS[0]} -eq 0

# The verification manual: builds, runs the Verification* suites, writes docs/verification.md.
verification: build
	@$(PYTHON) scripts/verification_report.py --binary $(BUILD)/tests/deploydyn_tests --out docs/verification.md

clean:
	rm -rf build results
