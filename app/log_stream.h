// An std::ostream whose complete lines go to a callback (the run directory's log), for
// library code that reports progress on a stream.
#pragma once

#include <functional>
#include <ostream>
#include <streambuf>
#include <string>

namespace vulnus::app
{
class LineCallbackBuffer : public std::streambuf
{
public:
  explicit LineCallbackBuffer(std::function<void(const std::string&)> sink) : sink(std::move(sink)) {}
  ~LineCallbackBuffer() override
  {
    if (!line.empty())
      sink(line);
  }

protected:
  int_type overflow(const int_type c) override
  {
    if (c == traits_type::eof())
      return c;
    if (c == '\n')
    {
      sink(line);
      line.clear();
    }
    else
      line.push_back(static_cast<char>(c));
    return c;
  }

private:
  std::function<void(const std::string&)> sink;
  std::string line;
};

class LogStream : public std::ostream
{
public:
  explicit LogStream(std::function<void(const std::string&)> sink)
    : std::ostream(nullptr), buffer(std::move(sink))
  {
    rdbuf(&buffer);
  }

private:
  LineCallbackBuffer buffer;
};
} // namespace vulnus::app
