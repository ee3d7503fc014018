// The files radiant writes: exclusive temporaries, outputs committed together, and the checks
// made before any work (src/output/).
#include <doctest/doctest.h>

#include <sys/stat.h>

#include <filesystem>
#include <set>

#include "output/output_paths.h"
#include "output/output_set.h"
#include "output/temporary_registry.h"
#include "support/fifo_reader.h"
#include "support/test_support.h"

using namespace radiant;
using namespace radiant::test;
namespace fs = std::filesystem;

TEST_CASE("temporary file: hidden beside its target, the extension kept, a fresh unguessable name, mode 0666 & ~umask") {
  ScratchDir dir("temporary-name");
  std::string target = dir.file("render.exr").string();
  std::set<std::string> names;
  mode_t mask = umask(022);
  umask(mask);
  for (int i = 0; i < 20; ++i) {
    TemporaryFile file(target);
    fs::path path = file.path();
    CHECK(path.parent_path() == dir.path);
    CHECK(path.filename().string().rfind(".render.tmp-", 0) == 0);
    CHECK(path.extension() == ".exr");
    CHECK(path.filename().string().size() == std::string(".render.tmp-").size() + 12 + 4);
    struct stat status;
    REQUIRE(lstat(path.c_str(), &status) == 0);
    CHECK(S_ISREG(status.st_mode));
    CHECK((status.st_mode & 0777) == (0666 & ~mask));
    names.insert(path.string());
  }
  CHECK(names.size() == 20);
  CHECK(fs::is_empty(dir.path));  // each removed when it went out of scope uncommitted
}

TEST_CASE("output set: nothing reaches a target until commit, then every target at once") {
  ScratchDir dir("output-set");
  fs::path image = dir.write("image.png", "old image"), stats = dir.file("stats.json");
  {
    OutputSet outputs;
    outputs.create(image.string()).write("new image");
    outputs.create(stats.string()).write("new stats");
    CHECK(read_bytes(image) == "old image");
    CHECK_FALSE(fs::exists(stats));
  }  // not committed: both temporaries go, the targets stay as they were
  CHECK(read_bytes(image) == "old image");
  CHECK_FALSE(fs::exists(stats));
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);
  OutputSet outputs;
  outputs.create(image.string()).write("new image");
  outputs.create(stats.string()).write("new stats");
  outputs.commit();
  CHECK(read_bytes(image) == "new image");
  CHECK(read_bytes(stats) == "new stats");
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 2);
}

TEST_CASE("output set: a file left out of the commit is removed and its target kept") {
  ScratchDir dir("output-set-remove");
  fs::path csv = dir.file("report.csv"), chart = dir.write("report.png", "old chart");
  OutputSet outputs;
  outputs.create(csv.string()).write("a,b\n");
  TemporaryFile& drawn = outputs.create(chart.string());
  outputs.remove(drawn);
  outputs.commit();
  CHECK(read_bytes(csv) == "a,b\n");
  CHECK(read_bytes(chart) == "old chart");
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 2);
}

TEST_CASE("output place: a missing folder, a file for a folder and a folder for the file are refused, naming the target") {
  ScratchDir dir("output-place");
  dir.write("file.txt", "x");
  fs::create_directory(dir.file("folder"));
  CHECK_NOTHROW(check_output_place(dir.file("new.png").string()));
  CHECK_NOTHROW(check_output_place(dir.file("file.txt").string()));  // replaced, as asked
  CHECK_THROWS_WITH(check_output_place(dir.file("no/new.png").string()), doctest::Contains("does not exist"));
  CHECK_THROWS_WITH(check_output_place(dir.file("file.txt/new.png").string()), doctest::Contains("file.txt/new.png"));
  CHECK_THROWS_WITH(check_output_place(dir.file("folder").string()), doctest::Contains("it is a folder"));
  // A folder to be created needs a writable existing ancestor.
  CHECK_NOTHROW(check_output_folder(dir.file("a/b/c").string()));
  CHECK_THROWS_WITH(check_output_folder(dir.file("file.txt/c").string()), doctest::Contains("file.txt/c"));
  CHECK_THROWS_WITH(check_output_folder(dir.file("file.txt").string()), doctest::Contains("is not a folder"));
}

TEST_CASE("distinct files: the same file by path spelling, symlink or hard link is refused, repeated inputs are fine") {
  ScratchDir dir("distinct");
  fs::path scene = dir.write("scene.gltf", "{}");
  fs::create_symlink(scene, dir.file("link.gltf"));
  fs::create_hard_link(scene, dir.file("hard.gltf"));
  auto refused = [&](const std::string& output) {
    DistinctFiles files;
    files.add_input({"the scene", scene.string()});
    files.add_input({"the scene", scene.string()});
    try {
      files.add_output({"--stats", output});
    } catch (const std::invalid_argument& e) {
      CHECK(std::string(e.what()).find("the same file as the scene") != std::string::npos);
      return true;
    }
    return false;
  };
  CHECK(refused(scene.string()));
  CHECK(refused((dir.path / "." / "scene.gltf").string()));
  CHECK(refused(dir.file("link.gltf").string()));
  CHECK(refused(dir.file("hard.gltf").string()));
  CHECK_FALSE(refused(dir.file("stats.json").string()));
  // Two outputs that do not exist yet: the same when their normalised paths are.
  DistinctFiles outputs;
  outputs.add_output({"-o", dir.file("new/../out.png").string()});
  CHECK_THROWS_AS(outputs.add_output({"--diff", dir.file("out.png").string()}), std::invalid_argument);
  CHECK_NOTHROW(outputs.add_output({"--stats", dir.file("out.json").string()}));
}

TEST_CASE("temporary registry: the signal handler's sweep unlinks every live temporary, and only those") {
  ScratchDir dir("registry");
  fs::path kept = dir.write("kept.png", "committed earlier");
  {
    TemporaryFile image(dir.file("out.png").string()), stats(dir.file("stats.json").string());
    image.write("partial");
    CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 3);
    remove_registered_temporaries();  // what a second SIGINT does before _exit
    CHECK_FALSE(fs::exists(image.path()));
    CHECK_FALSE(fs::exists(stats.path()));
  }
  CHECK(read_bytes(kept) == "committed earlier");
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);
}

TEST_CASE("output target: a FIFO is streamed through to its reader and stays a FIFO") {
  ScratchDir dir("output-fifo");
  fs::path fifo = dir.file("pipe.json");
  REQUIRE(mkfifo(fifo.c_str(), 0600) == 0);
  FifoReader reader(fifo);
  {
    OutputSet outputs;
    outputs.create(fifo.string()).write("streamed bytes");
    outputs.commit();
  }
  CHECK(reader.finish() == "streamed bytes");
  struct stat status;
  REQUIRE(lstat(fifo.c_str(), &status) == 0);
  CHECK(S_ISFIFO(status.st_mode));
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);
}

TEST_CASE("output target: a symlink to /dev/null is written through, the link and the device stay as they are") {
  ScratchDir dir("output-null-link");
  fs::path link = dir.file("null.json");
  fs::create_symlink("/dev/null", link);
  OutputSet outputs;
  outputs.create(link.string()).write("discarded");
  outputs.commit();
  CHECK(fs::is_symlink(link));
  CHECK(fs::read_symlink(link) == "/dev/null");
  struct stat status;
  REQUIRE(stat("/dev/null", &status) == 0);
  CHECK(S_ISCHR(status.st_mode));
  CHECK(std::distance(fs::directory_iterator(dir.path), fs::directory_iterator()) == 1);
}

TEST_CASE("output target: a symlink to a regular file replaces the file it leads to, the link stays a link") {
  ScratchDir dir("output-file-link");
  fs::create_directory(dir.file("real"));
  fs::path file = dir.write("real/image.png", "old"), link = dir.file("image.png");
  fs::create_symlink(file, link);
  OutputSet outputs;
  TemporaryFile& temporary = outputs.create(link.string());
  CHECK(fs::path(temporary.path()).parent_path() == dir.file("real"));  // renamed within its folder
  temporary.write("new");
  outputs.commit();
  CHECK(fs::is_symlink(link));
  CHECK(read_bytes(file) == "new");
}

TEST_CASE("output target: a read-only file is refused, also for root, and left as it is") {
  ScratchDir dir("output-read-only");
  fs::path file = dir.write("golden.png", "golden");
  REQUIRE(chmod(file.c_str(), 0444) == 0);
  CHECK_THROWS_WITH(check_output_place(file.string()), ("cannot write '" + file.string() + "': it is read-only").c_str());
  OutputSet outputs;
  CHECK_THROWS_WITH(outputs.create(file.string()), ("cannot write '" + file.string() + "': it is read-only").c_str());
  CHECK(read_bytes(file) == "golden");
  struct stat status;
  REQUIRE(stat(file.c_str(), &status) == 0);
  CHECK((status.st_mode & 0777) == 0444);
}

TEST_CASE("output target: a dangling symlink is refused, and a replaced file keeps its permission bits") {
  ScratchDir dir("output-dangling");
  fs::path link = dir.file("out.png");
  fs::create_symlink(dir.file("missing/nothing.png"), link);
  CHECK_THROWS_WITH(check_output_place(link.string()),
                    ("cannot write '" + link.string() + "': it is a symbolic link to a missing file").c_str());
  fs::path kept = dir.write("kept.json", "old");
  REQUIRE(chmod(kept.c_str(), 0640) == 0);
  OutputSet outputs;
  outputs.create(kept.string()).write("new");
  outputs.commit();
  struct stat status;
  REQUIRE(stat(kept.c_str(), &status) == 0);
  CHECK((status.st_mode & 0777) == 0640);
  CHECK(read_bytes(kept) == "new");
}
