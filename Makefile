# stochtex top-level entry points. See README.md.
BUILD_DIR ?= build
BUILD_TYPE ?= Release
JOBS ?= $(shell nproc)

.PHONY: all deps build demo test golden-update bench clean

all: build

deps:
	@bash scripts/install-deps.sh

build: deps
	cmake -S . -B $(BUILD_DIR) -DCMAKE_BUILD_TYPE=$(BUILD_TYPE)
	cmake --build $(BUILD_DIR) -j $(JOBS)

# Renders the embedded default gallery (every preset, its colormap and noises).
demo: build
	$(BUILD_DIR)/bin/stochtex gallery -o out/gallery

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

# Rewrites tests/golden/*.png after an intended change of the pixels (docs/TESTING.md).
golden-update: build
	cmake --build $(BUILD_DIR) --target golden-update

bench: build
	$(BUILD_DIR)/bin/stochtex_bench

clean:
	rm -rf $(BUILD_DIR) out
