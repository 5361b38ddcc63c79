// writeRecords formats blocks of records in parallel: the text must still be
// every record once, in order, across block boundaries.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "number_text.hpp"
#include "record_writer.hpp"

namespace cadmedial {
namespace {

void appendRecord(std::size_t i, std::string& out) {
  appendInteger(out, i);
  out += ' ';
  appendNumber(out, 0.1 * static_cast<double>(i));
  if (i % 7 == 0) out += " seventh";  // records of different lengths
  out += '\n';
}

TEST(RecordWriter, SameTextAsOneThreadInOrder) {
  for (const std::size_t count : {0u, 1u, 8191u, 8192u, 8193u, 5u * 8192u + 17u}) {
    std::string expected = "header\n";
    for (std::size_t i = 0; i < count; ++i) appendRecord(i, expected);
    std::ostringstream stream;
    stream << "header\n";
    writeRecords(stream, count, appendRecord);
    SCOPED_TRACE(count);
    EXPECT_EQ(stream.str(), expected);
  }
}

}  // namespace
}  // namespace cadmedial
