# Two commands for a fresh Debian 12 machine (as root): `make demo` and `make test`.
# Both install the missing Debian packages first (idempotent), then configure and build.

DEBIAN_PACKAGES := cmake make g++ pkg-config git clang-format \
  libeigen3-dev libsuitesparse-dev libcgal-dev libyaml-cpp-dev libcli11-dev libfmt-dev \
  nlohmann-json3-dev libglpk-dev libcairo2-dev libgtest-dev libgmock-dev libbenchmark-dev \
  libopenblas0-pthread python3-meshio python3-numpy \
  pybind11-dev python3-dev python3-pytest python3-matplotlib python3-scipy \
  jupyter-nbconvert python3-ipykernel \
  clang libclang-rt-14-dev
# pybind11-dev and python3-dev build the Python module (docs/python.md); pytest runs its tests,
# matplotlib draws the Python example's plot, scipy is the neighbour one test runs it beside;
# nbconvert and the Python kernel execute the example notebook.
# clang and its compiler runtime (libFuzzer, ASan, UBSan: libclang-rt-14-dev, which clang only
# recommends) build the sanitizer build and its fuzz targets (docs/fuzzing.md).
# The PETSc backend (docs/parallel.md): PETSc with Open MPI, hypre and MUMPS. `make test`
# installs it and tests the backend on one and two processes; `make build` and `make demo` do not
# need it, and build the backend when it is installed.
PETSC_PACKAGES := libpetsc-real-dev
# Optional peers the benchmarks compare with, installed by `make bench` only (bench/CMakeLists.txt
# builds without them): Siconos Numerics' LCP solvers.
BENCH_PACKAGES := libsiconos-numerics-dev

JOBS ?= $(shell nproc)
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)
DEMO_OUT ?= results/jointed_rock_mass

.PHONY: all deps petsc-deps bench-deps build build-asan build-fuzz test fuzz-long demo bench format clean

all: build

# Installs the Debian packages of the list $(1) that are missing (idempotent: asks dpkg first).
define install_missing
@missing=$$(for p in $(1); do \
  dpkg-query -W -f='$${Status}\n' $$p 2>/dev/null | grep -q '^install ok installed$$' || echo $$p; \
done); \
if [ -n "$$missing" ]; then \
  echo "Installing missing Debian packages:" $$missing; \
  $(SUDO) apt-get update && \
  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y --no-install-recommends $$missing; \
fi
endef

deps:
	$(call install_missing,$(DEBIAN_PACKAGES))

petsc-deps: deps
	$(call install_missing,$(PETSC_PACKAGES))

bench-deps: deps
	$(call install_missing,$(BENCH_PACKAGES))

build: deps
	cmake --preset release
	cmake --build --preset release -j $(JOBS)

build-asan: deps
	cmake --preset asan-ubsan
	cmake --build --preset asan-ubsan -j $(JOBS)

# The sanitizer build (clang: ASan, UBSan) holds the tests and the fuzz targets, whose short
# runs are tests of its own. The fuzz preset builds the fuzz targets alone, for long runs.
build-fuzz: deps
	cmake --preset fuzz
	cmake --build --preset fuzz -j $(JOBS)

# petsc-deps first: the release build finds PETSc when it is configured.
test: petsc-deps build build-asan
	ctest --preset release
	ctest --preset asan-ubsan

# Each fuzz target for FUZZ_RUNS executions (docs/fuzzing.md), one after the other, at the
# lowest priority; a finding stops it with the input in build/fuzz/fuzz/<target>/findings/. An
# input may take 60 s here, not 10: at nice 19 on a busy machine, one that takes 0.6 s alone
# waited 12 s for the processor.
FUZZ_RUNS ?= 1000000
FUZZ_TARGETS := case_reader block_generation gmsh_mesh
fuzz-long: build-fuzz
	@for t in $(FUZZ_TARGETS); do \
	  echo "== fuzz target $$t: $(FUZZ_RUNS) executions"; \
	  nice -n 19 build/fuzz/fuzz/$$t/run.sh -runs=$(FUZZ_RUNS) -timeout=60 || exit 1; \
	done

DEMO_CASES := case1_vertical case2_horizontal case3_biaxial

demo: build
	@for c in $(DEMO_CASES); do \
	  echo "== example 1 (Zhang & Lu, Table 2): $$c"; \
	  ./build/release/bimrock run examples/jointed_rock_mass/$$c.yaml --output $(DEMO_OUT)/$$c || exit 1; \
	done
	@echo "== example 2 (Zhang & Lu): pull-out of a half-brick, collapse at P = 2C = 40 kN"
	@./build/release/bimrock run examples/pull_out/case.yaml --output results/pull_out
	@echo
	@echo "Results of the demo (SI units):"
	@echo "  $(DEMO_OUT)/<case>/: summary.json (mean strain of the mass), blocks.csv, interfaces.csv,"
	@echo "    results.pvd + vtk/ to open in ParaView; examples/jointed_rock_mass/README.md explains them."
	@echo "  results/pull_out/: plot_A.png (load-displacement at A), collapse.png (the mechanism),"
	@echo "    history.csv, summary.json (collapse bracket); examples/pull_out/README.md explains them."

bench: bench-deps
	cmake --preset bench
	cmake --build --preset bench -j $(JOBS)
	./build/bench/bench/bimrock_bench

format:
	find src tests bench fuzz python examples -name '*.cpp' -o -name '*.hpp' | xargs clang-format -i

clean:
	rm -rf build
