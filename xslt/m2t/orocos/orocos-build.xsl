<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/orocos/orocos-build.xsl - CMakeLists.txt and package.xml.

  Reads:   o:deployment of urn:robomda:psm-orocos:1.
  Writes:  strings (file contents), wrapped into fs:file by main.xsl.
  Params:  model-dir-from-output (../common/text.xsl).  Errors: none.

  The atomic-code library of each o:library is found through a cache
  variable <PKG>_<LIB>_DIR (PATH), defaulting to the artifact path: as is
  when absolute, else ${CMAKE_CURRENT_SOURCE_DIR}/<model-dir-from-output>/<path>.
  When that directory has a CMakeLists.txt it is added with
  add_subdirectory(DIR <lib>-build) and its target linked; otherwise a
  prebuilt library named after the target is searched in DIR, DIR/lib and
  DIR/build. Its include dir and DIR itself are include directories. A
  package moved away from the model (a workspace, a release) stops at
  configure time with a FATAL_ERROR that names the -D option to set,
  never with an unexplained NOTFOUND.
  The headers of the library's include dir are installed beside the
  generated headers (include/orocos/<pkg>/), which include them with
  quotes, so a downstream package that uses the installed headers builds.
  Without a build type the package builds as Release.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:o="urn:robomda:psm-orocos:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    exclude-result-prefixes="#all">

  <xsl:function name="fp:cmakelists" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:variable name="pkg" as="xs:string" select="$deployment/@package"/>
    <xsl:variable name="sources" as="xs:string*"
        select="$deployment/o:task-context ! (concat('src/', @generated-class, '.cpp'), if (@kind eq 'base') then concat('src/', @class, '.cpp') else ()),
                'src/components.cpp'"/>
    <xsl:variable name="headers" as="xs:string*"
        select="$deployment/o:task-context ! (concat('include/', $pkg, '/', @generated-class, '.hpp'),
                                     if (@kind eq 'base') then concat('include/', $pkg, '/', @class, '.hpp') else ()),
                $deployment/o:types/(o:struct | o:enum) ! ('include/' || @header)"/>
    <xsl:sequence select="fp:lines((
        fp:banner('# ', $fp:build-xsl, concat('model ''', $deployment/@model-name, ''''), false()),
        'cmake_minimum_required(VERSION 3.5)',
        concat('project(', $pkg, ')'),
        '',
        '# Components run in real time: build optimised unless a build type is given.',
        'if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)',
        '  set(CMAKE_BUILD_TYPE Release CACHE STRING &quot;Build type (Release unless set)&quot; FORCE)',
        'endif()',
        '',
        '# RTT 2.10 headers do not compile as C++20: pin the standard.',
        'set(CMAKE_CXX_STANDARD 14)',
        'set(CMAKE_CXX_STANDARD_REQUIRED ON)',
        fp:cmake-warnings(),
        'set(CMAKE_CXX_EXTENSIONS OFF)',
        '',
        'find_package(OROCOS-RTT REQUIRED)',
        'if(NOT OROCOS-RTT_FOUND)',
        '  message(FATAL_ERROR &quot;Could not find Orocos-RTT. Source env.sh first.&quot;)',
        'endif()',
        'include(${OROCOS-RTT_USE_FILE_PATH}/UseOROCOS-RTT.cmake)',
        '# RTT''s headers as system headers: the warnings are the generated code''s, not RTT''s own',
        'include_directories(SYSTEM ${OROCOS-RTT_INCLUDE_DIRS})',
        '',
        'include_directories(${CMAKE_CURRENT_SOURCE_DIR}/include)',
        $deployment/o:library ! fp:library-subdirectory(.),
        '',
        '# One component library with every component type (src/components.cpp).',
        concat('orocos_component(', $pkg, ' ', string-join($sources, ' '), ')'),
        $deployment/o:library ! fp:library-link(., $pkg),
        if ($deployment/o:types) then (
          '',
          '# The RTT typekit of the model''s data types (src/typekit.cpp); the deploy files load it first.',
          concat('orocos_typekit(', $deployment/o:types/@typekit, ' src/typekit.cpp)')) else (),
        '',
        concat('orocos_install_headers(', string-join($headers, ' '), ')'),
        $deployment/o:library ! fp:library-install-headers(., $pkg),
        'orocos_generate_package()',
        fp:orocos-tests($deployment)))"/>
  </xsl:function>

  <!-- ctest (after make install): each process's self-check
       (deploy/<process>-check.lua: every component Running with its
       modelled period, affinity and property values, every connection
       connected and carrying data); a process of several (CORBA) needs
       the others running, which its start script does: not a test here -->
  <xsl:function name="fp:orocos-tests" as="xs:string+">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:variable name="alone" as="element(o:process)*" select="$deployment/o:process[not(@corba = 'true')]"/>
    <xsl:sequence select="
        '',
        '# ctest, after make install: the deployment checks itself (deploy/*-check.lua)',
        'enable_testing()',
        'find_program(ROBOMDA_RTTLUA rttlua)',
        if (empty($alone)) then '# (every process is one of several: run the start scripts, then each -check.lua)' else (
        'if(ROBOMDA_RTTLUA)',
        $alone ! ('  add_test(NAME ' || @file || '-check COMMAND ${CMAKE_COMMAND} -E env',
                  '    &quot;RTT_COMPONENT_PATH=${CMAKE_INSTALL_PREFIX}/lib/orocos:$ENV{RTT_COMPONENT_PATH}&quot;',
                  '    &quot;LD_LIBRARY_PATH=${CMAKE_INSTALL_PREFIX}/lib:$ENV{LD_LIBRARY_PATH}&quot;',
                  '    ${ROBOMDA_RTTLUA} ${CMAKE_CURRENT_SOURCE_DIR}/deploy/' || @file || '-check.lua)',
                  '  set_tests_properties(' || @file || '-check PROPERTIES PASS_REGULAR_EXPRESSION &quot;DEPLOY-RESULT: OK&quot;)'),
        'endif()')"/>
  </xsl:function>

  <xsl:function name="fp:library-subdirectory" as="xs:string*">
    <xsl:param name="lib" as="element(o:library)"/>
    <xsl:variable name="value" as="xs:string" select="concat('${', $lib/@cmake-var, '}')"/>
    <xsl:sequence select="
        '',
        concat('# atomic-code library ''', $lib/@name, ''' (artifact path ''', $lib/@path, ''', CMake target ', $lib/@target, ')'),
        concat('set(', $lib/@cmake-var, ' &quot;', fp:library-dir($lib), '&quot; CACHE PATH'),
        concat('    &quot;Directory of the atomic-code library ', $lib/@name, '&quot;)'),
        concat('if(NOT IS_DIRECTORY &quot;', $value, '&quot;)'),
        concat('  message(FATAL_ERROR &quot;atomic-code library ', $lib/@name, ': no directory ', $value,
               '; give its place with -D', $lib/@cmake-var, '=DIR&quot;)'),
        'endif()',
        concat('if(EXISTS &quot;', $value, '/CMakeLists.txt&quot; AND NOT TARGET ', $lib/@target, ')'),
        concat('  add_subdirectory(&quot;', $value, '&quot; ', $lib/@build-dir, ')'),
        'endif()',
        concat('include_directories(&quot;', $value, '/', $lib/@include-dir, '&quot; &quot;', $value, '&quot;)')"/>
  </xsl:function>

  <xsl:function name="fp:library-link" as="xs:string*">
    <xsl:param name="lib" as="element(o:library)"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:variable name="value" as="xs:string" select="concat('${', $lib/@cmake-var, '}')"/>
    <xsl:variable name="found" as="xs:string" select="replace($lib/@cmake-var, '_DIR$', '_LIBRARY')"/>
    <xsl:sequence select="
        concat('if(TARGET ', $lib/@target, ')'),
        concat('  target_link_libraries(', $pkg, ' ', $lib/@target, ')'),
        'else()',
        concat('  find_library(', $found, ' NAMES ', $lib/@target),
        concat('    PATHS &quot;', $value, '&quot; &quot;', $value, '/lib&quot; &quot;', $value, '/build&quot; NO_DEFAULT_PATH)'),
        concat('  if(', $found, ')'),
        concat('    target_link_libraries(', $pkg, ' ${', $found, '})'),
        '  else()',
        concat('    message(FATAL_ERROR &quot;atomic-code library ', $lib/@name, ': neither a CMakeLists.txt nor a built library ',
               $lib/@target, ' in ', $value, '; give its place with -D', $lib/@cmake-var, '=DIR&quot;)'),
        '  endif()',
        'endif()'"/>
  </xsl:function>

  <!-- the atomic headers the installed generated headers include -->
  <xsl:function name="fp:library-install-headers" as="xs:string">
    <xsl:param name="lib" as="element(o:library)"/>
    <xsl:param name="pkg" as="xs:string"/>
    <xsl:sequence select="concat('install(DIRECTORY &quot;${', $lib/@cmake-var, '}/', $lib/@include-dir, '/&quot; DESTINATION include/orocos/', $pkg,
        ' FILES_MATCHING PATTERN &quot;*.h&quot; PATTERN &quot;*.hh&quot; PATTERN &quot;*.hpp&quot; PATTERN &quot;*.hxx&quot;)')"/>
  </xsl:function>

  <xsl:function name="fp:package-xml" as="xs:string">
    <xsl:param name="deployment" as="element(o:deployment)"/>
    <xsl:sequence select="fp:lines((
        '&lt;?xml version=&quot;1.0&quot;?&gt;',
        '&lt;!--',
        fp:indent(2, fp:banner('', $fp:build-xsl, concat('model ''', fp:xml-text($deployment/@model-name), ''''), false())),
        '--&gt;',
        '&lt;package format=&quot;3&quot;&gt;',
        concat('  &lt;name&gt;', $deployment/@package, '&lt;/name&gt;'),
        f:package-manifest-fields(concat('  &lt;description&gt;Orocos RTT components of model ', fp:xml-text($deployment/@model-name), ', generated by robomda.&lt;/description&gt;')),
        '',
        '  &lt;buildtool_depend&gt;cmake&lt;/buildtool_depend&gt;',
        '  &lt;depend&gt;rtt&lt;/depend&gt;',
        '  &lt;exec_depend&gt;ocl&lt;/exec_depend&gt;',
        if ($deployment/o:process/@corba = 'true') then (
          '  &lt;!-- CORBA between processes: omniORB (RTT''s CORBA transport; the start scripts use omniNames and nameclt,',
          '       Debian omniorb-nameserver and omniorb) --&gt;',
          '  &lt;exec_depend&gt;omniorb&lt;/exec_depend&gt;') else (),
        if ($deployment/(o:connection[@transport eq 'ros'] | o:connection/o:stream[@transport eq 'ros'])) then (
          '  &lt;!-- streams to ROS topics: the rtt_ros_integration packages the deployment imports --&gt;',
          fp:deploy-imports-ros() ! ('  &lt;exec_depend&gt;' || . || '&lt;/exec_depend&gt;')) else (),
        '',
        '  &lt;export&gt;',
        '    &lt;build_type&gt;cmake&lt;/build_type&gt;',
        '  &lt;/export&gt;',
        '&lt;/package&gt;'))"/>
  </xsl:function>
</xsl:stylesheet>
