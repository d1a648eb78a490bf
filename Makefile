# Thin driver: Debian packages, CMake build, ctest, demo, benchmarks, formatting.
BUILD   ?= build
ASAN_BUILD ?= build-asan
FUZZ_SECONDS ?= 60
FUZZ_MODEL_MUTANTS ?= 5000
FUZZ_MODEL_SEED ?= 1
PYTHON  := /usr/bin/python3
JOBS    ?= $(shell nproc)
SUDO    := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

DEBS := cmake make g++ pkg-config git freecad \
	libocct-foundation-dev libocct-modeling-data-dev libocct-modeling-algorithms-dev libtbb-dev \
	libcgal-dev libboost-dev libeigen3-dev pybind11-dev python3-dev nlohmann-json3-dev libassimp-dev \
	python3-ezdxf python3-pytest python3-numpy libgtest-dev libbenchmark-dev \
	libpolyclipping-dev libstb-dev python3-pil python3-svgwrite python3-reportlab python3-matplotlib python3-pypdf librecad \
	xvfb xauth clang-format black patch clang libclang-rt-dev llvm

.PHONY: all deps build test test-matrix demo bench lint format install install-dev clean fuzz asan layers corpus

all: build

deps:
	@missing=$$(for p in $(DEBS); do \
	  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q "install ok installed" || echo $$p; \
	done); \
	if [ -n "$$missing" ]; then \
	  echo "Installing Debian packages:" $$missing; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DPython3_EXECUTABLE=$(PYTHON)

build: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS)
	@$(PYTHON) tools/write_launcher.py $(BUILD)

test: build
	cd $(BUILD) && ctest --output-on-failure -j 2

# Debian 13 / FreeCAD 1.0 and sid / FreeCAD 1.1 in chroots under $(BUILD)/matrix (README, Platforms).
test-matrix:
	@command -v debootstrap >/dev/null || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq --no-install-recommends debootstrap; }
	$(SUDO) $(PYTHON) tools/test_matrix.py --build $(BUILD) --jobs $(JOBS)

demo: build
	$(PYTHON) tools/run_demo.py --build $(BUILD) --out out/demo

bench: build
	$(BUILD)/bench/popup_bench --benchmark_min_time=0.2
	POPUP_BUILD_DIR=$(CURDIR)/$(BUILD) FREECAD_USER_HOME=$(CURDIR)/$(BUILD)/sandbox/home \
	  $(PYTHON) bench/freecad_recompute_bench.py
	POPUP_BUILD_DIR=$(CURDIR)/$(BUILD) $(PYTHON) bench/sheets_bench.py
	POPUP_BUILD_DIR=$(CURDIR)/$(BUILD) $(PYTHON) bench/fit_e2e_bench.py
	POPUP_BUILD_DIR=$(CURDIR)/$(BUILD) $(PYTHON) bench/animate_e2e_bench.py

# libFuzzer targets (fuzz/, docs/RELIABILITY.md): FUZZ_SECONDS per target, corpora kept in
# $(BUILD)/fuzz-work between runs. Then load_model on FUZZ_MODEL_MUTANTS mutated model files
# (a deterministic driver: load_model reads in a child process, out of libFuzzer's sight).
fuzz: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target popup_fuzzers load_model_fuzz
	$(PYTHON) fuzz/run_fuzzers.py --build-dir $(BUILD)/fuzzers --work $(BUILD)/fuzz-work \
	  --seconds $(FUZZ_SECONDS)
	$(BUILD)/tests/core/load_model_fuzz --iterations $(FUZZ_MODEL_MUTANTS) --seed $(FUZZ_MODEL_SEED) \
	  --dir $(BUILD)/fuzz-work/load_model

# The core, the bindings and the C++ and Python suites under ASan + UBSan (docs/RELIABILITY.md).
asan: deps
	$(PYTHON) tools/run_asan.py --build $(ASAN_BUILD) --jobs $(JOBS)

# The layers drawn from the code's includes and imports (tools/layers.py, docs/DESIGN.md "Layers"):
# out/layers.png, and every arrow that runs back up or circle, if any (exit 1).
layers:
	$(PYTHON) tools/layers.py --png out/layers.png

# The realistic corpus (tools/make_corpus.py, docs/CORPUS.md) into $(BUILD)/corpus, and a preview
# of each model (its file read back through popupcore) with the contact sheet beside them.
corpus: deps $(BUILD)/CMakeCache.txt
	cmake --build $(BUILD) -j $(JOBS) --target popupcore
	$(PYTHON) tools/make_corpus.py --out $(BUILD)/corpus
	PYTHONPATH=$(CURDIR)/$(BUILD)/python $(PYTHON) tools/corpus_previews.py --corpus $(BUILD)/corpus \
	  --out $(BUILD)/corpus/previews --sheet $(BUILD)/corpus/previews/contact_sheet.png

lint: deps
	clang-format --dry-run --Werror $$(git ls-files '*.cpp' '*.hpp')
	black --check -l 100 -q $$(git ls-files '*.py')

format: deps
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')
	black -l 100 -q $$(git ls-files '*.py')

# Into the user Mod folder of the FreeCAD installed here, which FreeCAD names (tools/install_addon.py).
install-dev:
	$(PYTHON) tools/install_addon.py --build $(BUILD) --link

install: build
	$(PYTHON) tools/install_addon.py --build $(BUILD)

clean:
	@if [ -d $(BUILD)/matrix ]; then $(SUDO) $(PYTHON) tools/test_matrix.py --build $(BUILD) --unmount; fi
	rm -rf --one-file-system $(BUILD) $(ASAN_BUILD) out
