# The two commands a newcomer needs: `make render` and `make test`. Both install what is missing first.
BUILD ?= build
JOBS ?= 2

.PHONY: deps build render test sanitize fuzz clean format benchmarks

deps:
	@tools/install-deps.sh

build: deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release
	cmake --build $(BUILD) -j $(JOBS)

render: build
	$(BUILD)/fragpath render -o cornell.png

test: build
	LP_NUM_THREADS=2 ctest --test-dir $(BUILD) --output-on-failure -j 1

# BENCHMARKS.md's at-a-glance table from one run, stamped with the commit, date and machine (about half an
# hour on 2 idle cores; tools/benchmarks.sh --quick checks the script in a minute).
benchmarks: build
	tools/benchmarks.sh

# The whole test suite built with AddressSanitizer and UBSan (our code; Mesa itself is not instrumented).
sanitize: deps
	cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFP_SANITIZE=ON
	cmake --build build-asan -j $(JOBS)
	LP_NUM_THREADS=2 ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 \
		ctest --test-dir build-asan --output-on-failure -j 1
	@echo "leak check of one render (LeakSanitizer; Mesa's own leaks suppressed in tools/lsan.supp)"
	LP_NUM_THREADS=2 ASAN_OPTIONS=detect_leaks=1 LSAN_OPTIONS=suppressions=$(CURDIR)/tools/lsan.supp \
		build-asan/fragpath render --size 16x16 --spp 2 --quiet -o build-asan/leak_check.exr

# libFuzzer on the OBJ/MTL loader, the scene file and the glTF loader, FUZZ_SECONDS each (default 60).
fuzz: deps
	tools/fuzz.sh

format:
	clang-format -i $$(git ls-files 'src/*.cpp' 'src/*.h' 'tests/*.cpp' 'tests/*.h')

clean:
	rm -rf $(BUILD)
