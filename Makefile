# feedflow: one-command setup. `make demo` and `make test` install what is missing, build and
# run. Everything the project needs is a Debian 12 package listed here.
SHELL := /bin/bash
BUILD ?= build
JOBS ?= $(shell nproc 2>/dev/null || echo 2)
CMAKE_FLAGS ?=
ifeq ($(CI),true)
CMAKE_FLAGS += -DFEEDFLOW_WERROR=ON
endif

DEB_PACKAGES := cmake make g++ pkg-config \
	libeigen3-dev libsundials-dev libgsl-dev libopenmpi-dev openmpi-bin libhdf5-dev \
	libosmesa6-dev libtomlplusplus-dev nlohmann-json3-dev libcli11-dev libcairo2-dev \
	libgtest-dev libbenchmark-dev poppler-utils fonts-dejavu-core
SUDO := $(shell [ "$$(id -u)" = 0 ] || echo sudo)

.PHONY: deps build demo test validate clean

# Installs only the packages that are missing; with everything present it only checks.
deps:
	@installed=$$(dpkg-query -W -f='$${Package} $${db:Status-Abbrev}\n' $(DEB_PACKAGES) 2>/dev/null | awk '$$2 == "ii" {print $$1}'); \
	missing=""; \
	for p in $(DEB_PACKAGES); do \
	  grep -qx "$$p" <<< "$$installed" || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  echo "make deps: installing$$missing"; \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get update -qq && \
	  $(SUDO) env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing; \
	fi

$(BUILD)/CMakeCache.txt:
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release $(CMAKE_FLAGS)

build: deps $(BUILD)/CMakeCache.txt
	cmake $(CMAKE_FLAGS) $(BUILD) >/dev/null
	cmake --build $(BUILD) -j $(JOBS)

demo: build
	./$(BUILD)/feedflow design cases/pilot_hopper.toml --report

test: build
	ctest --test-dir $(BUILD) --output-on-failure -j $(JOBS) -LE long

validate: build
	ctest --test-dir $(BUILD) --output-on-failure -L long

clean:
	rm -rf $(BUILD) out
