# The two commands a newcomer needs: `make render` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS ?= 2

.PHONY: deps build render test clean format

deps:
	@tools/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j $(JOBS)

render: build
	$(BUILD)/fragpath render -o cornell.png

test: build
	LP_NUM_THREADS=2 ctest --test-dir $(BUILD) --output-on-failure -j 1

format:
	clang-format -i $$(git ls-files 'src/*.cpp' 'src/*.h' 'tests/*.cpp' 'tests/*.h')

clean:
	rm -rf $(BUILD)
