# The two commands a new user needs: `make run` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS ?= $(shell nproc)
PORT ?= 8080

.PHONY: all setup configure build run test bench format clean

all: build

setup:
	bash scripts/setup

configure: setup
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release

build: configure
	cmake --build $(BUILD) -j$(JOBS)

# Serves http://127.0.0.1:$(PORT) with the built-in `default` map (and `web/` as the dashboard).
run: build
	./$(BUILD)/bin/lightprobe-server --port $(PORT)

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS)

bench: build
	bash bench/run_all.sh $(BUILD)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD)
