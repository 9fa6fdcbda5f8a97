#!/usr/bin/env bash
# `./run-tests --sanitize [all|corpus]`: builds sbsim and its C++ tests with AddressSanitizer and
# UndefinedBehaviorSanitizer (LeakSanitizer on) into build/asan, then runs ctest and, against that
# build, the whole pytest suite (`all`, the default: end to end, the hostile-input corpus and the
# fuzzing), or builds only the program and runs the corpus and the fuzzing against it (`corpus`:
# what CI runs, see run-tests).
# Any sanitizer report fails the run: ASan/LSan exit with code 23, UBSan halts on the first error.
source "$(dirname "${BASH_SOURCE[0]}")/setup.sh"
cd "$SBSIM_ROOT"
scope="${1:-all}"
case "$scope" in all | corpus) ;; *) say "--sanitize takes all or corpus, not '$scope'"; exit 2 ;; esac
flags="-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=undefined"
say "configuring build/asan (sanitizers: address, undefined, leak)"
cmake -S . -B build/asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSBSIM_BUILD_TESTS=ON \
  -DPython_EXECUTABLE="$VENV/bin/python" -DCMAKE_CXX_FLAGS="$flags" -DSBSIM_ALLOCATOR=system \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" >build/asan-configure.log 2>&1 \
  || { tail -n 30 build/asan-configure.log >&2; exit 1; }
# `corpus` drives the program only: building the C++ tests too would double CI's sanitizer time.
targets=()
if [ "$scope" = "corpus" ]; then targets=(--target sbsim); fi
cmake --build build/asan -j"${CMAKE_BUILD_PARALLEL_LEVEL}" "${targets[@]}" >build/asan-build.log 2>&1 \
  || { tail -n 40 build/asan-build.log >&2; say "sanitizer build failed; full log: build/asan-build.log"; exit 1; }
export ASAN_OPTIONS="detect_leaks=1:exitcode=23:abort_on_error=0:strict_init_order=1"
export LSAN_OPTIONS="suppressions=$SBSIM_ROOT/tools/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1:exitcode=23"
export SBSIM_EXECUTABLE="$SBSIM_ROOT/build/asan/sbsim"
export PYTHONPATH="$SBSIM_ROOT/python${PYTHONPATH:+:$PYTHONPATH}"  # this tree's storyboard and sbsim packages
status=0
if [ "$scope" = "all" ]; then
  # The layer probes only compile; every other C++ test runs instrumented.
  ctest --test-dir build/asan --output-on-failure -j2 -E '^layers\.' || status=1
  "$VENV/bin/python" -m pytest tests/python -q -p no:cacheprovider || status=1
else
  "$VENV/bin/python" -m pytest tests/python/test_corpus.py tests/python/test_fuzz.py -q -p no:cacheprovider || status=1
fi
exit $status
