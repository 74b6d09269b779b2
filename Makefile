# stochtex top-level entry points. See README.md.
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)

.PHONY: all deps build demo test fuzz golden-update bench clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)
	cmake --build $(BUILD_DIR) -j $(JOBS)

# Renders the embedded default gallery (every preset, its colormap and noises).
demo: build
	$(BUILD_DIR)/bin/stochtex gallery -o out/gallery

# Every test, then the sanitizer build (clang, ASan + UBSan with
# float-cast-overflow): its unit-test subset and a short run of each fuzz target.
test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)
	bash scripts/sanitize-test.sh $(SANITIZE_FUZZ_SECONDS)

# Builds the libFuzzer targets (clang) in build-fuzz and runs each for SECONDS
# (docs/TESTING.md). `make test` only replays their stored inputs.
SECONDS ?= 60
SANITIZE_FUZZ_SECONDS ?= 5
fuzz: deps
	bash scripts/fuzz.sh $(SECONDS)

# Rewrites tests/golden/*.png after an intended change of the pixels (docs/TESTING.md).
golden-update: build
	cmake --build $(BUILD_DIR) --target golden-update

bench: build
	$(BUILD_DIR)/bin/stochtex_bench

clean:
	rm -rf $(BUILD_DIR) build-fuzz out
