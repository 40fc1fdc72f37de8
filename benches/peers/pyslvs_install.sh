#!/bin/bash
# How pyslvs 22.7.0 was installed into /tmp/pyslvs-venv (Python 3.11.7, no wheel exists for 3.11).
set -e
python3.11 -m venv /tmp/pyslvs-venv
/tmp/pyslvs-venv/bin/pip install "cython==3.0.0b2" setuptools wheel "numpy<2" lark-parser
/tmp/pyslvs-venv/bin/pip download pyslvs==22.7.0 --no-deps --no-binary :all: -d /tmp/pyslvs-work/sdist
cd /tmp/pyslvs-work/sdist && tar xzf pyslvs-22.7.0.tar.gz
rm -rf /tmp/pyslvs-work/build-src && cp -r pyslvs-22.7.0 /tmp/pyslvs-work/build-src && cd /tmp/pyslvs-work/build-src
# only change: legacy C power semantics for Cython 3 final/betas (f_planar.pyx `** 1.5` in nogil)
sed -i "s/'cdivision': True}/'cdivision': True, 'cpow': True}/" setup.py
/tmp/pyslvs-venv/bin/pip install --no-build-isolation .
