#!/usr/bin/env bash
# Remakes the embedded sample CT (head-phantom-ct.json and .i16.zlib beside this script)
# from the shared Philips head-phantom series. Usage: make-sample-ct.sh BUILD_DIR
# [SHARED_DATA_DIR]; BUILD_DIR holds a build with DICOM import (bin/voxray-make-sample).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=${1:?usage: make-sample-ct.sh BUILD_DIR [SHARED_DATA_DIR]}
data=${2:-$here/../../../shared/data}
cmake --build "$build" --target voxray-make-sample
"$build/bin/voxray-make-sample" "$data/dicom/ct-philips-phantom" \
  "$here/head-phantom-ct.json" "$here/head-phantom-ct.i16.zlib"
