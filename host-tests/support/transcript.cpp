#include "transcript.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "frame_text.hpp"

namespace costa::test {

bool parseTranscript(const std::string& text, const std::string& path, Transcript* transcript,
                     std::string* error) {
  transcript->path = path;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string content = raw.substr(0, raw.find('#'));
    std::istringstream words(content);
    std::string keyword;
    if (!(words >> keyword)) {
      continue;
    }
    std::string rest;
    std::getline(words, rest);
    const auto fail = [&](const std::string& message) {
      *error = path + ":" + std::to_string(line) + ": " + message;
      return false;
    };
    TranscriptStep step;
    step.line = line;
    step.text = content;
    if (keyword == "device") {
      std::istringstream(rest) >> transcript->device;
      continue;
    }
    if (keyword == "node-id") {
      if (!(std::istringstream(rest) >> transcript->nodeId) || transcript->nodeId < 1 ||
          transcript->nodeId > 127) {
        return fail("node-id must be 1..127");
      }
      continue;
    }
    if (keyword == "rx" || keyword == "tx") {
      std::string frameError;
      if (!host::parseFrame(rest, &step.frame, &frameError, &step.wildcards)) {
        return fail(frameError);
      }
      if (keyword == "rx" && step.wildcards != 0U) {
        return fail("'xx' is only allowed in expected (tx) frames");
      }
      step.kind =
          keyword == "rx" ? TranscriptStep::Kind::kReceive : TranscriptStep::Kind::kTransmit;
    } else if (keyword == "wait") {
      long long ms = -1;
      if (!(std::istringstream(rest) >> ms) || ms < 0) {
        return fail("wait needs a number of milliseconds");
      }
      step.kind = TranscriptStep::Kind::kWait;
      step.milliseconds = static_cast<uint64_t>(ms);
    } else if (keyword == "silence") {
      step.kind = TranscriptStep::Kind::kSilence;
    } else if (keyword == "sim") {
      step.kind = TranscriptStep::Kind::kSimulate;
      step.text = rest.substr(rest.find_first_not_of(' ') == std::string::npos
                                  ? rest.size()
                                  : rest.find_first_not_of(' '));
      while (!step.text.empty() && (step.text.back() == ' ' || step.text.back() == '\t')) {
        step.text.pop_back();
      }
      if (step.text.empty()) {
        return fail("sim needs a command");
      }
    } else if (keyword == "ignore") {
      unsigned long id = 0;
      std::istringstream idText(rest);
      if (!(idText >> std::hex >> id) || id > 0x7FF) {
        return fail("ignore needs an 11-bit CAN-ID in hex");
      }
      std::string more;
      if (idText >> more) {
        return fail("ignore takes one CAN-ID (one line each)");
      }
      transcript->ignored.push_back(static_cast<uint32_t>(id));
      continue;
    } else {
      return fail("unknown keyword '" + keyword + "'");
    }
    transcript->steps.push_back(step);
  }
  if (transcript->device.empty()) {
    *error = path + ": no 'device' line";
    return false;
  }
  return true;
}

bool loadTranscript(const std::string& path, Transcript* transcript, std::string* error) {
  std::ifstream file(path);
  if (!file) {
    *error = path + ": cannot open";
    return false;
  }
  std::stringstream content;
  content << file.rdbuf();
  return parseTranscript(content.str(), path, transcript, error);
}

std::vector<std::string> findTranscripts(const std::string& directory) {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(directory)) {
    if (entry.is_regular_file() && entry.path().extension() == ".transcript") {
      paths.push_back(entry.path().string());
    }
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace costa::test
