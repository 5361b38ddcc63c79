// Writes many text records (lines) in order, formatting them on all cores.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <ostream>
#include <string>

#include <tbb/parallel_pipeline.h>

namespace cadmedial {

// writeRecords (below) for records that go to several streams at once:
// `format(i, texts)` appends record i's text for streams[k] to texts[k], so
// what the texts share (the numbers of medial.obj's and medial.ma's vertex
// lines) is formatted once.
template <std::size_t N, typename Format>
void writeRecordsTo(const std::array<std::ostream*, N>& streams, std::size_t count, Format format) {
  constexpr std::size_t kBlock = 8192;  // records per block: ~0.5 MB of text
  constexpr std::size_t kBlocksInFlight = 8;
  using Texts = std::array<std::string, N>;
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
          tbb::make_filter<std::size_t, Texts>(tbb::filter_mode::parallel,
                                               [&](std::size_t first) {
                                                 Texts texts;
                                                 for (std::string& text : texts) text.reserve(64 * kBlock);
                                                 const std::size_t last = std::min(count, first + kBlock);
                                                 for (std::size_t i = first; i < last; ++i) format(i, texts);
                                                 return texts;
                                               }) &
          tbb::make_filter<Texts, void>(tbb::filter_mode::serial_in_order, [&](const Texts& texts) {
            for (std::size_t k = 0; k < N; ++k)
              streams[k]->write(texts[k].data(), static_cast<std::streamsize>(texts[k].size()));
          }));
}

// Appends records first .. count-1 to `stream`, in order: `format(i, text)`
// appends record i to `text`. Blocks of records are formatted in parallel
// and each block is written as soon as those before it are, so only a few
// blocks are in memory at once. Why: a 10^6-sample axis is ~1.2 GB of text
// over three files; built in one string per file it cost a page fault per
// 4 kB and that much memory, and formatted on one thread per file the
// largest file (.ma) set the write time.
template <typename Format>
void writeRecords(std::ostream& stream, std::size_t count, Format format) {
  writeRecordsTo<1>({&stream}, count, [&](std::size_t i, std::array<std::string, 1>& texts) { format(i, texts[0]); });
}

}  // namespace cadmedial
