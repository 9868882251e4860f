# The two commands a new user needs: `make run` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS ?= $(shell nproc)
PORT ?= 8080
DATA_DIR ?= tests/data

.PHONY: all setup setup-test setup-container configure configure-test server cli build run test test-container bench format clean

all: build

# What running needs; `setup-test` adds what the tests and benchmarks need.
setup:
	bash scripts/setup

setup-test:
	bash scripts/setup --test

setup-container:
	bash scripts/setup --test --container

# `make run` configures without the tests and benchmarks and builds only the server, so it needs
# neither their packages nor their build time; `make test` turns them back on in the same build folder.
configure: setup
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DLIGHTPROBE_BUILD_TESTS=OFF -DLIGHTPROBE_BUILD_BENCH=OFF

configure-test: setup-test
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release -DLIGHTPROBE_BUILD_TESTS=ON -DLIGHTPROBE_BUILD_BENCH=ON

server: configure
	cmake --build $(BUILD) -j$(JOBS) --target lightprobe-server

# The command-line tool, build/bin/lightprobe, beside the server.
cli: configure
	cmake --build $(BUILD) -j$(JOBS) --target lightprobe-server lightprobe

build: configure-test
	cmake --build $(BUILD) -j$(JOBS)

# Serves http://127.0.0.1:$(PORT) with the built-in `default` map, `web/` as the dashboard, and files
# under $(DATA_DIR) (the repository's small maps and models) loadable by path.
run: server
	./$(BUILD)/bin/lightprobe-server --port $(PORT) --data-dir $(DATA_DIR)

# Every test but the container image's (label `container`), which compiles the server in the image.
test: build
	ctest --test-dir $(BUILD) --output-on-failure -j$(JOBS) -LE container

# docker/Dockerfile built with podman and the API smoke test run inside (skipped without podman).
test-container: setup-container configure-test
	ctest --test-dir $(BUILD) --output-on-failure -L container

bench: build
	bash bench/run_all.sh $(BUILD)

format:
	clang-format -i $$(git ls-files '*.cpp' '*.hpp')

clean:
	rm -rf $(BUILD)
