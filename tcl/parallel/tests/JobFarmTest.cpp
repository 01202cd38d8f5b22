// SPDX-License-Identifier: MIT
#include "tcl/parallel/JobFarm.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <deque>
#include <map>
#include <mutex>
#include <thread>

#include "tcl/parallel/SerialCommunicator.h"

namespace dabs::parallel {
namespace {

/// Mailboxes of processes simulated by threads of this test: what MPI does between processes.
struct Mailboxes {
  std::mutex mutex;
  std::condition_variable arrived;
  std::map<std::pair<int, int>, std::deque<Communicator::Message>>
      boxes;  // (dest, tag) -> messages
};

/// One simulated process's view of the mailboxes (point-to-point only: what the farm uses).
class ThreadCommunicator final : public Communicator {
 public:
  ThreadCommunicator(Mailboxes& m, int rank, int size) : m_(m), rank_(rank), size_(size) {}
  int rank() const override { return rank_; }
  int size() const override { return size_; }
  void barrier() override {}
  void send(int dest, int tag, std::string_view text) override {
    std::lock_guard lock(m_.mutex);
    m_.boxes[{dest, tag}].push_back(Message{rank_, std::string(text)});
    m_.arrived.notify_all();
  }
  Message receive(int source, int tag) override {
    std::unique_lock lock(m_.mutex);
    for (;;) {
      auto& box = m_.boxes[{rank_, tag}];
      for (auto it = box.begin(); it != box.end(); ++it) {
        if (source == kAnySource || it->source == source) {
          Message message = *it;
          box.erase(it);
          return message;
        }
      }
      m_.arrived.wait(lock);
    }
  }
  std::optional<Message> tryReceive(int tag) override {
    std::lock_guard lock(m_.mutex);
    auto& box = m_.boxes[{rank_, tag}];
    if (box.empty()) return std::nullopt;
    Message message = box.front();
    box.pop_front();
    return message;
  }
  std::string broadcast(std::string text, int /*root*/) override { return text; }
  std::unique_ptr<Communicator> duplicate() override { return nullptr; }
  bool allowsServiceThread() const override { return true; }

 private:
  Mailboxes& m_;
  int rank_;
  int size_;
};

TEST(JobFarmTest, OneProcessRunsEveryJobInOrder) {
  SerialCommunicator comm;
  JobFarm farm(comm);
  std::vector<int> ran;
  std::map<int, std::string> stored;
  const int count = farm.run(
      {2, 0, 1},
      [&](int i) {
        ran.push_back(i);
        return std::string("r").append(std::to_string(i));
      },
      [&](int i, const std::string& r) { stored[i] = r; });
  EXPECT_EQ(count, 3);
  EXPECT_EQ(ran, (std::vector<int>{2, 0, 1}));
  EXPECT_EQ(stored, (std::map<int, std::string>{{0, "r0"}, {1, "r1"}, {2, "r2"}}));
}

// Three processes; process 1's jobs are slow, so the others take more of them: a job goes to
// whichever process is free, and process 0 runs jobs while it hands them out.
TEST(JobFarmTest, FreeProcessesTakeTheNextJobAndEveryResultIsStoredOnce) {
  Mailboxes mail;
  constexpr int kProcesses = 3;
  constexpr int kJobs = 30;
  std::vector<int> pending(kJobs);
  for (int i = 0; i < kJobs; ++i) pending[static_cast<std::size_t>(i)] = i;
  std::map<int, std::string> stored;
  std::mutex storedMutex;
  std::vector<int> ranByProcess(kProcesses, 0);
  std::vector<std::thread> processes;
  for (int rank = 0; rank < kProcesses; ++rank) {
    processes.emplace_back([&, rank] {
      ThreadCommunicator comm(mail, rank, kProcesses);
      JobFarm farm(comm);
      ranByProcess[static_cast<std::size_t>(rank)] = farm.run(
          rank == 0 ? pending : std::vector<int>{},
          [&](int i) {
            std::this_thread::sleep_for(std::chrono::milliseconds(rank == 1 ? 20 : 2));
            return "job " + std::to_string(i) + " on " + std::to_string(rank);
          },
          [&](int i, const std::string& r) {
            std::lock_guard lock(storedMutex);
            EXPECT_EQ(stored.count(i), 0u) << "job " << i << " stored twice";
            stored[i] = r;
          });
    });
  }
  for (auto& p : processes) p.join();
  ASSERT_EQ(stored.size(), static_cast<std::size_t>(kJobs));
  for (int i = 0; i < kJobs; ++i)
    EXPECT_EQ(stored[i].rfind("job " + std::to_string(i) + " on ", 0), 0u);
  EXPECT_EQ(ranByProcess[0] + ranByProcess[1] + ranByProcess[2], kJobs);
  EXPECT_GT(ranByProcess[0], 0);
  EXPECT_GT(ranByProcess[2], ranByProcess[1]);
}

}  // namespace
}  // namespace dabs::parallel
