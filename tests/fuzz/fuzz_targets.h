// The fuzz harnesses, one function per target, shared by the libFuzzer executables
// (fuzz_entry.cpp) and the corpus replay in inkray_tests (fuzz_corpus_test.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace inkray {

// Each runs one input and returns 0; a broken oracle calls fuzz_fail.
int fuzz_scene_reader(const std::uint8_t* data, std::size_t size);
int fuzz_obj_loader(const std::uint8_t* data, std::size_t size);
int fuzz_image_reader(const std::uint8_t* data, std::size_t size);
int fuzz_graph_compile(const std::uint8_t* data, std::size_t size);
int fuzz_partial_reader(const std::uint8_t* data, std::size_t size);
int fuzz_checkpoint_reader(const std::uint8_t* data, std::size_t size);
int fuzz_line_decisions_reader(const std::uint8_t* data, std::size_t size);
int fuzz_animation_tracks(const std::uint8_t* data, std::size_t size);

// Defined by whoever links the harnesses: fuzz_entry.cpp aborts, so libFuzzer saves the
// input as a crash; the replay test throws, so it can name the file and go on.
[[noreturn]] void fuzz_fail(const std::string& what);

}  // namespace inkray
