// The grader's own files, apart from the submission's (submission_files.hpp): the folders and copies
// of its private work tree, made for a job's uid, and the cache's folders, filled under a temporary
// name, published whole and trusted only while the manifest of their hashes holds.
#pragma once
#include <filesystem>
#include <string>
#include <sys/types.h>

namespace t10::grade {

// A file of the grader's (the host kit, a shader, a log) as text; throws t10::Error when it cannot be opened.
std::string readFile(const std::string& path);

// FNV-1a of `text`, in hexadecimal: names a cache folder after what it holds.
std::string hashOf(const std::string& text);
// The FNV-1a of a file's contents, read without following a symlink; "" when it cannot be read.
std::string fileHash(const std::string& path);

// ".<pid>.<counter>": a name no other grader or job of this one uses.
std::string uniqueSuffix();
// Renames `temporary` to `target`; when another grader got there first, keeps theirs.
void publishDirectory(const std::filesystem::path& temporary, const std::filesystem::path& target);

// The file in a cached folder listing the hash of every other file in it.
constexpr const char* kManifest = "manifest.t10";
void writeManifest(const std::filesystem::path& dir);
// Whether `dir` has a manifest and its files still match it.
bool manifestHolds(const std::filesystem::path& dir);

// Makes `dir` (if absent) with `mode`, owned by `owner` when not 0; throws t10::Error naming it.
void makeDir(const std::filesystem::path& dir, uid_t owner, mode_t mode);
// Copies a file the grader owns to `to` (which must not exist), close-on-exec, owned by `owner` when not 0.
void copyFile(const std::filesystem::path& from, const std::filesystem::path& to, mode_t mode, uid_t owner = 0);
// Copies a folder of regular files, each owned by `owner`.
void copyTree(const std::filesystem::path& from, const std::filesystem::path& to, uid_t owner);

} // namespace t10::grade
