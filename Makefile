# The two commands of the README: `make render` and `make test`. Both install what is missing first.
BUILD_DIR ?= build
JOBS ?= $(shell nproc)
WIDTH ?= 800
HEIGHT ?= 600

.PHONY: deps configure build render test clean

deps:
	@bash tools/install-deps.sh

configure: deps
	@cmake -S . -B $(BUILD_DIR) -G Ninja -DCMAKE_BUILD_TYPE=Release $(CMAKE_ARGS)

build: configure
	@cmake --build $(BUILD_DIR) -j $(JOBS)

render: build
	./$(BUILD_DIR)/snell render scenes/showcase.pov -o showcase.png -w $(WIDTH) -h $(HEIGHT) --aa 0.3

test: build
	cd $(BUILD_DIR) && ctest --output-on-failure -j $(JOBS)

clean:
	rm -rf $(BUILD_DIR) showcase.png
