#pragma once
// Kept equal to project(VERSION) in CMakeLists.txt (a test checks it).
#define NORMZOO_VERSION "0.1.0"
