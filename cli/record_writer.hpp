// Writes many text records (lines) in order, formatting them on all cores.
#pragma once

#include <algorithm>
#include <cstddef>
#include <ostream>
#include <string>

#include <tbb/parallel_pipeline.h>

namespace cadmedial {

// Appends records first .. count-1 to `stream`, in order: `format(i, text)`
// appends record i to `text`. Blocks of records are formatted in parallel
// and each block is written as soon as those before it are, so only a few
// blocks are in memory at once. Why: a 10^6-sample axis is ~1.2 GB of text
// over three files; built in one string per file it cost a page fault per
// 4 kB and that much memory, and formatted on one thread per file the
// largest file (.ma) set the write time.
template <typename Format>
void writeRecords(std::ostream& stream, std::size_t count, Format format) {
  constexpr std::size_t kBlock = 8192;  // records per block: ~0.5 MB of text
  constexpr std::size_t kBlocksInFlight = 8;
  std::size_t next = 0;
  tbb::parallel_pipeline(
      kBlocksInFlight,
      tbb::make_filter<void, std::size_t>(tbb::filter_mode::serial_in_order,
                                          [&](tbb::flow_control& control) -> std::size_t {
                                            if (next >= count) {
                                              control.stop();
                                              return 0;
                                            }
                                            const std::size_t first = next;
                                            next = std::min(count, next + kBlock);
                                            return first;
                                          }) &
          tbb::make_filter<std::size_t, std::string>(tbb::filter_mode::parallel,
                                                     [&](std::size_t first) {
                                                       std::string text;
                                                       text.reserve(64 * kBlock);
                                                       const std::size_t last = std::min(count, first + kBlock);
                                                       for (std::size_t i = first; i < last; ++i) format(i, text);
                                                       return text;
                                                     }) &
          tbb::make_filter<std::string, void>(tbb::filter_mode::serial_in_order, [&](const std::string& text) {
            stream.write(text.data(), static_cast<std::streamsize>(text.size()));
          }));
}

}  // namespace cadmedial
