// Captures what is written to file descriptor 2 (stderr) while it lives: the
// adapters' reports are checked by their text. POSIX (dup/dup2).
#pragma once

#include <unistd.h>

#include <cstdio>
#include <string>

namespace mj_test {

class StderrCapture {
 public:
  StderrCapture() : file_(std::tmpfile()), saved_(dup(2)) {
    std::fflush(stderr);
    dup2(fileno(file_), 2);
  }
  ~StderrCapture() {
    std::fflush(stderr);
    dup2(saved_, 2);
    close(saved_);
    std::fclose(file_);
  }
  StderrCapture(const StderrCapture&) = delete;
  StderrCapture& operator=(const StderrCapture&) = delete;

  // Everything written since construction.
  std::string text() {
    std::fflush(stderr);
    std::string out;
    std::rewind(file_);
    for (int c; (c = std::fgetc(file_)) != EOF;) out += char(c);
    return out;
  }

 private:
  std::FILE* file_;
  int saved_;
};

}  // namespace mj_test
