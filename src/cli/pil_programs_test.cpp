// The command lines duet pil runs, word for word: what QEMU 7.2 was checked to accept (docs/LINK.md).
#include "pil_programs.hpp"

#include <gtest/gtest.h>

namespace duet::cli {
namespace {

TEST(PilPrograms, QemuWithTheFirmwareItsUartsAndItsArguments) {
  const QemuSetup setup{"qemu-system-arm", "build/balbot-pil.elf", 3, 2.5, "/tmp/duet-pil-abc"};
  const std::vector<std::string> expected{
      "qemu-system-arm",
      "-machine",
      "mps2-an386",
      "-nographic",
      "-monitor",
      "none",
      "-kernel",
      "build/balbot-pil.elf",
      "-icount",
      "shift=3,align=off,sleep=off",  //
      "-semihosting-config",
      "enable=on,target=native,arg=balbot-pil.elf,arg=--link,arg=/tmp/duet-pil-abc,arg=--duration,"
      "arg=2.5",
      "-chardev",
      "socket,id=xcp,path=/tmp/duet-pil-abc/xcp.sock,server=on,wait=off",
      "-serial",
      "chardev:xcp",
      "-chardev",
      "socket,id=app,path=/tmp/duet-pil-abc/app.sock,server=on,wait=off",
      "-serial",
      "chardev:app",
      "-serial",
      "null",  //
      "-serial",
      "stdio"};
  EXPECT_EQ(qemu_command(setup), expected);
}

TEST(PilPrograms, CommasInQemuValuesAreDoubled) {
  const QemuSetup setup{"qemu", "a,b.elf", 2, std::nullopt, "/tmp/x,y"};
  const std::vector<std::string> command = qemu_command(setup);
  EXPECT_EQ(command[11], "enable=on,target=native,arg=a,,b.elf,arg=--link,arg=/tmp/x,,y");  // and no --duration
  EXPECT_EQ(command[13], "socket,id=xcp,path=/tmp/x,,y/xcp.sock,server=on,wait=off");
}

TEST(PilPrograms, TheBridgeOnQemusSockets) {
  const std::vector<std::string> expected{"duet-bridge",          "--channel", "unix:/tmp/d/xcp.sock", "--app-channel",
                                          "unix:/tmp/d/app.sock", "--listen",  "127.0.0.1:5555",       "--websocket",
                                          "127.0.0.1:8765"};
  EXPECT_EQ(bridge_command({"duet-bridge", "/tmp/d", "127.0.0.1:5555", "127.0.0.1:8765"}), expected);
}

TEST(PilPrograms, TheBridgeBesideDuetOrOnThePath) {
  EXPECT_EQ(default_bridge("/nonexistent/build/src/cli/duet"), "duet-bridge");
  EXPECT_EQ(default_bridge(""), "duet-bridge");  // /proc/self/exe could not be read
  EXPECT_EQ(default_bridge(DUET_PROGRAM),
            std::filesystem::path{DUET_PROGRAM}.parent_path().parent_path() / "bridge" / "duet-bridge");
}

TEST(PilPrograms, ShortestNumbers) {
  EXPECT_EQ(shortest(3), "3");
  EXPECT_EQ(shortest(2.5), "2.5");
  EXPECT_EQ(shortest(0.1), "0.1");
  EXPECT_EQ(shortest(1e-5), "1e-05");
}

}  // namespace
}  // namespace duet::cli
