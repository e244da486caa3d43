// OpenGL entry points for the whole project: the generated glad 4.3 core loader.
#pragma once
#include <glad/gl.h>
