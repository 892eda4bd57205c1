#include "evolve/record/checkpoint_writer.hpp"

namespace robozoo {

CheckpointWriter::CheckpointWriter(std::string path, bool background, int generations_on_disk)
    : path_(std::move(path)), background_(background), written_(generations_on_disk) {}

CheckpointWriter::~CheckpointWriter() {
  if (thread_.joinable()) thread_.join();
}

void CheckpointWriter::wait() {
  if (thread_.joinable()) thread_.join();
  if (error_) {
    std::exception_ptr e = error_;
    error_ = nullptr;
    std::rethrow_exception(e);
  }
}

void CheckpointWriter::write(Checkpoint c, int generations_done) {
  wait();
  if (!background_) {
    write_checkpoint(path_, c);
    written_ = generations_done;
    return;
  }
  thread_ = std::thread([this, c = std::move(c), generations_done] {
    try {
      write_checkpoint(path_, c);
      written_ = generations_done;
    } catch (...) {
      error_ = std::current_exception();  // read by wait() after the join
    }
  });
}

}  // namespace robozoo
