// Hostile programs for sandbox-run's tests: each mode does one thing a malicious or broken
// submission would do, and reports on stdout what it managed. Exit status 0 means "the
// attempt succeeded", 3 means "the attempt was refused" (the report says how).
//
//   hostile spin                 ignore SIGTERM/SIGINT/SIGHUP and loop forever
//   hostile burn                 loop forever on the CPU (default signal handling)
//   hostile orphans MARKER N     start N children that leave the session, ignore SIGTERM and
//                                SIGHUP, and sleep (argv carries MARKER); the parent exits 0
//   hostile forkmany N           fork up to N sleeping children; prints how many it got
//   hostile alloc MB             allocate MB MiB and touch every page
//   hostile writefile PATH MB    write MB MiB to PATH, 64 KiB at a time
//   hostile openmany N           open up to N descriptors; prints how many it got
//   hostile connect PORT         TCP connect to 127.0.0.1:PORT
//   hostile listen PORTFILE S    (the test's trusted side) listen on 127.0.0.1, write the port
//                                to PORTFILE, accept connections for S seconds
//   hostile read PATH            read PATH
//   hostile write PATH...        create each PATH and write to it (0: all written, 3: none,
//                                4: some)
//   hostile fake CODE [PATH]     print a fake pass and a fake sandbox-run result line, try to
//                                write "exit=0" to PATH, then exit with CODE
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>
#include <vector>

namespace {

constexpr int kRefused = 3;

int refused(const char* what) {
  std::printf("refused: %s: %s\n", what, std::strerror(errno));
  return kRefused;
}

void ignore_termination() {
  std::signal(SIGTERM, SIG_IGN);
  std::signal(SIGINT, SIG_IGN);
  std::signal(SIGHUP, SIG_IGN);
}

[[noreturn]] void spin_forever() {
  volatile unsigned long counter = 0;
  for (;;) counter = counter + 1;
}

int orphans(const char* self, const char* marker, int n) {
  for (int i = 0; i < n; ++i) {
    pid_t pid = fork();
    if (pid < 0) return refused("fork");
    if (pid == 0) {
      setsid();  // leave the session and process group of the sandboxed command
      if (fork() != 0) _exit(0);  // double fork: the sleeper is nobody's child
      ignore_termination();
      execl("/proc/self/exe", self, "sleeper", marker, static_cast<char*>(nullptr));
      _exit(1);
    }
    waitpid(pid, nullptr, 0);
  }
  std::printf("started %d orphans\n", n);
  return 0;
}

int forkmany(int n) {
  int got = 0;
  for (; got < n; ++got) {
    pid_t pid = fork();
    if (pid < 0) break;
    if (pid == 0) {
      ignore_termination();
      pause();
      _exit(0);
    }
  }
  std::printf("forked %d\n", got);
  return got == n ? 0 : kRefused;
}

int alloc(long mb) {
  const std::size_t bytes = static_cast<std::size_t>(mb) * 1024 * 1024;
  auto* p = static_cast<volatile char*>(std::malloc(bytes));
  if (p == nullptr) return refused("malloc");
  for (std::size_t i = 0; i < bytes; i += 4096) p[i] = 1;
  std::printf("allocated %ld MiB\n", mb);
  std::free(const_cast<char*>(p));
  return 0;
}

int writefile(const char* path, long mb) {
  int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) return refused("open");
  std::vector<char> chunk(64 * 1024, 'x');
  const long chunks = mb * 16;
  for (long i = 0; i < chunks; ++i) {
    if (write(fd, chunk.data(), chunk.size()) != static_cast<ssize_t>(chunk.size())) {
      return refused("write");
    }
  }
  close(fd);
  std::printf("wrote %ld MiB\n", mb);
  return 0;
}

int openmany(int n) {
  int got = 0;
  for (; got < n; ++got) {
    if (open("/dev/null", O_RDONLY) < 0) break;
  }
  std::printf("opened %d\n", got);
  return got == n ? 0 : kRefused;
}

int connect_to(int port) {
  int s = socket(AF_INET, SOCK_STREAM, 0);
  if (s < 0) return refused("socket");
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(static_cast<uint16_t>(port));
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (connect(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) return refused("connect");
  std::printf("connected to 127.0.0.1:%d\n", port);
  return 0;
}

int listen_on(const char* portfile, int seconds) {
  int s = socket(AF_INET, SOCK_STREAM, 0);
  if (s < 0) return refused("socket");
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = 0;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  socklen_t len = sizeof addr;
  if (bind(s, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 || listen(s, 8) != 0 ||
      getsockname(s, reinterpret_cast<sockaddr*>(&addr), &len) != 0) {
    return refused("listen");
  }
  {
    std::string tmp = std::string(portfile) + ".tmp";
    FILE* f = std::fopen(tmp.c_str(), "w");
    if (f == nullptr) return refused("portfile");
    std::fprintf(f, "%d\n", ntohs(addr.sin_port));
    std::fclose(f);
    std::rename(tmp.c_str(), portfile);
  }
  alarm(static_cast<unsigned>(seconds));  // the listener never outlives its test
  for (;;) {
    int c = accept(s, nullptr, nullptr);
    if (c >= 0) close(c);
  }
}

int read_path(const char* path) {
  FILE* f = std::fopen(path, "r");
  if (f == nullptr) return refused("open");
  char buf[256];
  std::size_t n = std::fread(buf, 1, sizeof buf, f);
  std::fclose(f);
  std::printf("read %zu bytes: %.*s\n", n, static_cast<int>(n), buf);
  return 0;
}

bool write_path(const char* path) {
  FILE* f = std::fopen(path, "w");
  if (f == nullptr || std::fputs("written by the sandboxed command\n", f) < 0 || std::fclose(f) != 0) {
    std::printf("refused: %s: %s\n", path, std::strerror(errno));
    return false;
  }
  std::printf("wrote %s\n", path);
  return true;
}

int write_paths(int count, char** paths) {
  int written = 0;
  for (int i = 0; i < count; ++i) written += write_path(paths[i]) ? 1 : 0;
  return written == count ? 0 : written == 0 ? kRefused : 4;
}

int fake(int code, const char* status_path) {
  std::printf("All tests passed (42 assertions in 7 test cases)\n");
  std::fprintf(stderr, "sandbox-run: result=exited exit=0 wall_ms=1 mechanism=bwrap\n");
  if (status_path != nullptr) {
    if (FILE* f = std::fopen(status_path, "w")) {
      std::fputs("result=exited\nexit=0\n", f);
      std::fclose(f);
      std::printf("overwrote %s\n", status_path);
    } else {
      std::printf("refused: status file: %s\n", std::strerror(errno));
    }
  }
  std::fflush(nullptr);
  std::exit(code);
}

int usage() {
  std::fprintf(stderr, "usage: hostile MODE [ARGS] (see the comment at the top of hostile.cpp)\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  if (argc < 2) return usage();
  const std::string mode = argv[1];
  auto arg = [&](int i) -> const char* { return i < argc ? argv[i] : nullptr; };
  auto num = [&](int i) { return arg(i) ? std::atol(arg(i)) : 0L; };

  if (mode == "spin") {
    ignore_termination();
    spin_forever();
  }
  if (mode == "burn") spin_forever();
  if (mode == "sleeper") {
    for (;;) pause();
  }
  if (mode == "orphans" && arg(2)) return orphans(argv[0], arg(2), static_cast<int>(num(3)));
  if (mode == "forkmany") return forkmany(static_cast<int>(num(2)));
  if (mode == "alloc") return alloc(num(2));
  if (mode == "writefile" && arg(2)) return writefile(arg(2), num(3));
  if (mode == "openmany") return openmany(static_cast<int>(num(2)));
  if (mode == "connect") return connect_to(static_cast<int>(num(2)));
  if (mode == "listen" && arg(2)) return listen_on(arg(2), static_cast<int>(num(3)));
  if (mode == "read" && arg(2)) return read_path(arg(2));
  if (mode == "write" && arg(2)) return write_paths(argc - 2, argv + 2);
  if (mode == "fake") return fake(static_cast<int>(num(2)), arg(3));
  return usage();
}
