<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/ros2/main.xsl - ROS PSM (ros-version 2) -> file set (an ament package).

  Reads:   urn:robomda:psm-ros:1 (schemas/psm-ros/1/psm-ros.xsd), from
           xslt/m2m/ros/psm.xsl with ros-version=2.
  Writes:  urn:robomda:fileset:1 (schemas/fileset/1/fileset.xsd), target "ros2":
             include/<pkg>/<Class>.hpp, src/<Class>.cpp, src/<exe>.cpp  per node
             include/<pkg>/<Class>Base.hpp, and include/<pkg>/<Class>Impl.hpp,
             src/<Class>Impl.cpp (mode user) per node without a realizing class
             include/<pkg>/lifecycle/<Class>.hpp, src/lifecycle/<Class>.cpp
                                     per node with a managed instance
             src/lifecycle_manager.cpp  when a host has a lifecycle manager
             src/<subsystem>_coordinator.cpp  per job coordinator (ros2-jobs.xsl)
             msg/<Type>.msg          per generated message
             CMakeLists.txt, package.xml
             launch/<model>.launch.xml, launch/<model>_<host>.launch.xml,
             launch/<model>_<set>.launch.xml
             config/<instance>.yaml, config/<instance>.user.yaml (mode user)
             test/test_<model>_launch.py  the system's launch test (ros2-test.xsl)
           One fs:file a line, as f:indent (common/indent.xsl) would indent
           the file set, written so directly (t:indented-content: no copy of
           all the text).
  Params:  model-dir-from-output (xslt/m2t/ros-common/ros-text.xsl).
  Errors:  none (the PSM is complete and valid).
  Modules: ../../common/sequence.xsl, ../ros-common/ros-text.xsl, ../common/user-class.xsl,
           ../ros-common/ros-user.xsl, ros2-cpp.xsl, ros2-build.xsl, ros2-launch.xsl, ros2-lifecycle.xsl,
           ../common/jobs.xsl, ../ros-common/ros-jobs.xsl, ros2-jobs.xsl, ../ros-common/ros-test.xsl, ros2-test.xsl.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-ros:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:f="urn:robomda:xslt:function"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    xmlns:t="urn:robomda:xslt:template"
    exclude-result-prefixes="#all">

  <xsl:include href="../../common/indent.xsl"/>
  <xsl:include href="../common/text.xsl"/>
  <xsl:include href="../common/package-manifest.xsl"/>
  <xsl:include href="../common/data-types.xsl"/>
  <xsl:include href="../../common/naming.xsl"/>
  <xsl:include href="../../common/sequence.xsl"/>
  <xsl:include href="../ros-common/ros-text.xsl"/>
  <xsl:include href="../common/user-class.xsl"/>
  <xsl:include href="../ros-common/ros-user.xsl"/>
  <xsl:include href="ros2-cpp.xsl"/>
  <xsl:include href="ros2-build.xsl"/>
  <xsl:include href="ros2-launch.xsl"/>
  <xsl:include href="ros2-lifecycle.xsl"/>
  <xsl:include href="../common/jobs.xsl"/>
  <xsl:include href="../ros-common/ros-jobs.xsl"/>
  <xsl:include href="ros2-jobs.xsl"/>
  <xsl:include href="../ros-common/ros-test.xsl"/>
  <xsl:include href="ros2-test.xsl"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8" cdata-section-elements="fs:file"/>
  <xsl:mode name="m:emit-files" on-no-match="fail"/>

  <xsl:variable name="fp:cpp-xsl" as="xs:string" select="'m2t/ros2/ros2-cpp.xsl'"/>
  <xsl:variable name="fp:build-xsl" as="xs:string" select="'m2t/ros2/ros2-build.xsl'"/>
  <xsl:variable name="fp:launch-xsl" as="xs:string" select="'m2t/ros2/ros2-launch.xsl'"/>
  <xsl:variable name="fp:lifecycle-xsl" as="xs:string" select="'m2t/ros2/ros2-lifecycle.xsl'"/>
  <xsl:variable name="fp:jobs-xsl" as="xs:string" select="'m2t/ros2/ros2-jobs.xsl'"/>

  <xsl:template match="r:package" mode="m:emit-files" as="element(fs:files)">
    <xsl:variable name="pkg" as="xs:string" select="@name"/>
    <xsl:variable name="package" as="element(r:package)" select="."/>
    <xsl:variable name="files" as="element(fs:file)*">
      <xsl:for-each select="r:node">
        <xsl:sequence select="fp:file(concat('include/', $pkg, '/', @class, '.hpp'), 'generated', $fp:cpp-xsl, fp:ros2-header(.))"/>
        <xsl:sequence select="fp:file(concat('src/', @class, '.cpp'), 'generated', $fp:cpp-xsl, fp:ros2-source(.))"/>
        <xsl:sequence select="fp:file(concat('src/', @executable, '.cpp'), 'generated', $fp:cpp-xsl, fp:ros2-main(.))"/>
        <!-- no realizing class: <Class>Base and the user's <Class>Impl (ros-user.xsl) -->
        <xsl:sequence select="fp:ros-user-files(.)"/>
      </xsl:for-each>
      <xsl:for-each select="r:node[@lifecycle-type-name]">
        <xsl:sequence select="fp:file(concat('include/', $pkg, '/lifecycle/', @class, '.hpp'), 'generated', $fp:lifecycle-xsl,
                                      fp:ros2-lifecycle-header(.))"/>
        <xsl:sequence select="fp:file(concat('src/lifecycle/', @class, '.cpp'), 'generated', $fp:lifecycle-xsl, fp:ros2-lifecycle-source(.))"/>
      </xsl:for-each>
      <xsl:for-each select="r:coordinator">
        <xsl:sequence select="fp:file(concat('src/', @executable, '.cpp'), 'generated', $fp:jobs-xsl, fp:ros2-coordinator(.))"/>
      </xsl:for-each>
      <xsl:if test="r:host[@lifecycle-manager]">
        <xsl:sequence select="fp:file('src/lifecycle_manager.cpp', 'generated', $fp:lifecycle-xsl, fp:ros2-lifecycle-manager(.))"/>
      </xsl:if>
      <xsl:sequence select="fp:ros-type-files(.)"/>
      <xsl:sequence select="fp:file('CMakeLists.txt', 'generated', $fp:build-xsl, fp:ros2-cmakelists(.))"/>
      <xsl:sequence select="fp:file('package.xml', 'generated', $fp:build-xsl, fp:ros2-package-xml(.))"/>
      <xsl:sequence select="fp:file(fp:ros2-launch-test-path(.), 'generated', $fp:test-xsl, fp:ros2-launch-test(.))"/>
      <xsl:sequence select="fp:file(concat('launch/', @deploy-name, '.launch.xml'), 'generated', $fp:launch-xsl, fp:ros2-top-launch(.))"/>
      <xsl:for-each select="r:host">
        <xsl:sequence select="fp:file(concat('launch/', $package/@deploy-name, '_', @launch, '.launch.xml'), 'generated', $fp:launch-xsl,
                                      fp:ros2-host-launch($package, .))"/>
      </xsl:for-each>
      <xsl:for-each select="r:set">
        <xsl:sequence select="fp:file(concat('launch/', $package/@deploy-name, '_', @launch, '.launch.xml'), 'generated', $fp:launch-xsl,
                                      fp:ros2-set-launch($package, .))"/>
      </xsl:for-each>
      <!-- one parameter file per instance, keyed /** and loaded by that
           node only: it applies whatever namespace the node ends up in -->
      <xsl:for-each select="r:instance">
        <xsl:sequence select="fp:file(concat('config/', @name, '.yaml'), 'generated', $fp:launch-xsl, fp:ros2-params-yaml(.))"/>
        <xsl:sequence select="fp:file(concat('config/', @name, '.user.yaml'), 'user', $fp:launch-xsl,
            fp:user-params-yaml(concat('the tuned parameters of instance ', @name), concat('config/', @name, '.yaml'), $fp:launch-xsl,
                                ('/**:', '  ros__parameters: {}')))"/>
      </xsl:for-each>
    </xsl:variable>
    <fs:files target="ros2">
      <xsl:call-template name="t:indented-content">
        <xsl:with-param name="children" select="$files"/>
        <xsl:with-param name="margin" select="'&#10;'"/>
      </xsl:call-template>
    </fs:files>
  </xsl:template>
</xsl:stylesheet>
