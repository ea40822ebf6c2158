// An HDF5 id that closes itself when it goes out of scope; a negative id (HDF5's failure)
// throws Error with the caller's message instead of being kept.
#pragma once

#include <hdf5.h>

#include <string>

namespace vulnus::io
{
template <class Error>
class Hdf5Handle
{
public:
  Hdf5Handle(const hid_t id, herr_t (*close)(hid_t), const std::string& message)
      : id(id), close_function(close)
  {
    if (id < 0)
      throw Error(message);
  }
  ~Hdf5Handle() { close_function(id); }
  Hdf5Handle(const Hdf5Handle&) = delete;
  Hdf5Handle& operator=(const Hdf5Handle&) = delete;
  operator hid_t() const { return id; }

private:
  hid_t id;
  herr_t (*close_function)(hid_t);
};
} // namespace vulnus::io
