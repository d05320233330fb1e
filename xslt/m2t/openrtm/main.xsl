<?xml version="1.0" encoding="UTF-8"?>
<!--
  xslt/m2t/openrtm/main.xsl - OpenRTM PSM -> file set (the OpenRTM-aist 2.0 package text).

  Reads:   urn:robomda:psm-openrtm:1 (schemas/psm-openrtm/1/psm-openrtm.xsd),
           from xslt/m2m/openrtm/psm.xsl.
  Writes:  urn:robomda:fileset:1 (schemas/fileset/1/fileset.xsd), target "openrtm":
             include/<pkg>/<Class>.h, src/<Class>.cpp     per component (generated)
             include/<pkg>/<Class>Base.h, src/<Class>Base.cpp + user
             include/<pkg>/<Class>.h, src/<Class>.cpp (mode user) when the
             component has no realizing class
             rtc/<Class>/RTC.xml       per component: its RtcProfile
             idl/<Interface>.idl       per interface of a service port
             include/<Type>.hpp        per data type / enumeration the components use (m2t/common/data-types.xsl)
             idl/<pkg>_types.idl, include/<pkg>/<pkg>_types.h  the data types the data ports
                                       carry, and their conversions (openrtm-types.xsl)
             include/<pkg>/<pkg>_conf.h  the reader of structured configuration values,
                                       when a component has such a parameter (openrtm-types.xsl)
             CMakeLists.txt            finds OpenRTM-aist, compiles the IDL, one module (.so) per component
             conf/<instance>.conf      per instance: execution context rate, configuration set
             deploy/<process>.rtc.conf per manager: modules, components, connections, activation
             deploy/<model>.rtsys.xml  the RtsProfile of the system
             deploy/start_<host>.sh    per host: its managers in the modelled order
             src/<Subsystem>Coordinator.cpp  per subsystem with jobs: its job coordinator (openrtm-jobs.xsl)
  Params:  model-dir-from-output (xslt/m2t/common/text.xsl), package-version.
  Errors:  none (the PSM is complete and valid).
  Modules: ../common/text.xsl, ../common/user-class.xsl, ../common/data-types.xsl, openrtm-cpp.xsl, openrtm-types.xsl, openrtm-profile.xsl, openrtm-deploy.xsl,
           ../common/jobs.xsl, openrtm-jobs.xsl.
-->
<xsl:stylesheet version="3.0"
    xmlns:xsl="http://www.w3.org/1999/XSL/Transform"
    xmlns:xs="http://www.w3.org/2001/XMLSchema"
    xmlns:r="urn:robomda:psm-openrtm:1"
    xmlns:fs="urn:robomda:fileset:1"
    xmlns:fp="urn:robomda:xslt:function:private"
    xmlns:m="urn:robomda:xslt:mode"
    exclude-result-prefixes="#all">

  <xsl:include href="../common/text.xsl"/>
  <xsl:include href="../common/user-class.xsl"/>
  <xsl:include href="../common/data-types.xsl"/>
  <xsl:include href="openrtm-cpp.xsl"/>
  <xsl:include href="openrtm-types.xsl"/>
  <xsl:include href="openrtm-profile.xsl"/>
  <xsl:include href="openrtm-deploy.xsl"/>
  <xsl:include href="../common/jobs.xsl"/>
  <xsl:include href="openrtm-jobs.xsl"/>

  <xsl:param name="package-version" as="xs:string" select="''"/>
  <!-- the version of the system and its components' profiles: the package version, else 1.0.0 -->
  <xsl:variable name="fp:rtm-version" as="xs:string" select="($package-version[normalize-space(.)], '1.0.0')[1]"/>

  <xsl:output method="xml" indent="no" encoding="UTF-8" cdata-section-elements="fs:file"/>

  <xsl:variable name="fp:cpp-xsl" as="xs:string" select="'m2t/openrtm/openrtm-cpp.xsl'"/>
  <xsl:variable name="fp:profile-xsl" as="xs:string" select="'m2t/openrtm/openrtm-profile.xsl'"/>
  <xsl:variable name="fp:deploy-xsl" as="xs:string" select="'m2t/openrtm/openrtm-deploy.xsl'"/>
  <xsl:variable name="fp:jobs-xsl" as="xs:string" select="'m2t/openrtm/openrtm-jobs.xsl'"/>
  <xsl:mode name="m:emit-files" on-no-match="fail"/>
  <xsl:variable name="fp:file-margin" as="xs:string" select="'&#10;  '"/>

  <xsl:template match="/" as="document-node()">
    <xsl:document>
      <xsl:apply-templates select="r:system" mode="m:emit-files"/>
    </xsl:document>
  </xsl:template>

  <xsl:template match="r:system" mode="m:emit-files" as="element(fs:files)">
    <xsl:variable name="pkg" as="xs:string" select="@package"/>
    <xsl:variable name="system" as="element(r:system)" select="."/>
    <fs:files target="openrtm">
      <xsl:for-each select="r:component">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('include/', $pkg, '/', @generated-class, '.h'), 'generated', $fp:cpp-xsl, fp:rtm-header(.))"/>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('src/', @generated-class, '.cpp'), 'generated', $fp:cpp-xsl, fp:rtm-source(.))"/>
        <xsl:if test="@kind eq 'base'">
          <!-- user files as on every target: what they implement and what the base requires of
               them, so that the writer's drift checks (OUT003, OUT004) see them -->
          <xsl:variable name="requires" as="xs:string+"
              select="'RTC::ReturnCode_t onInitialize()', r:hook[@name ne 'configure'] ! fp:rtm-action-signature(@name)"/>
          <xsl:sequence select="$fp:file-margin, fp:user-class-file(concat('include/', $pkg, '/', @class, '.h'), $fp:cpp-xsl, ., $requires, fp:rtm-user-header(.))"/>
          <xsl:sequence select="$fp:file-margin, fp:user-class-file(concat('src/', @class, '.cpp'), $fp:cpp-xsl, ., $requires, fp:rtm-user-source(.))"/>
        </xsl:if>
        <xsl:sequence select="$fp:file-margin, fp:file(concat('rtc/', @class, '/RTC.xml'), 'generated', $fp:profile-xsl, fp:rtc-profile(., $fp:rtm-version))"/>
      </xsl:for-each>
      <xsl:for-each select="r:data-types">
        <xsl:variable name="definitions" as="element()*" select="r:enum | r:struct"/>
        <xsl:for-each select="$definitions">
          <xsl:sequence select="$fp:file-margin, fp:file('include/' || @header, 'generated', 'm2t/common/data-types.xsl',
                                        fp:type-header(., $definitions, $system/@model-name))"/>
        </xsl:for-each>
        <xsl:if test="$definitions[xs:boolean(@idl)]">
          <xsl:sequence select="$fp:file-margin, fp:file('idl/' || @idl || '.idl', 'generated', $fp:types-xsl, fp:rtm-types-idl(.))"/>
          <xsl:sequence select="$fp:file-margin, fp:file('include/' || $pkg || '/' || @idl || '.h', 'generated', $fp:types-xsl, fp:rtm-types-convert(.))"/>
        </xsl:if>
      </xsl:for-each>
      <xsl:if test="r:component/r:parameter[@kind]">
        <xsl:sequence select="$fp:file-margin, fp:file('include/' || $pkg || '/' || $pkg || '_conf.h', 'generated', $fp:types-xsl, fp:rtm-conf-header(.))"/>
      </xsl:if>
      <xsl:for-each select="r:coordinator">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('src/', @class, '.cpp'), 'generated', $fp:jobs-xsl, fp:rtm-coordinator(.))"/>
      </xsl:for-each>
      <xsl:for-each select="r:interface">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('idl/', @name, '.idl'), 'generated', $fp:cpp-xsl, fp:rtm-idl(.))"/>
      </xsl:for-each>
      <xsl:sequence select="$fp:file-margin, fp:file('CMakeLists.txt', 'generated', $fp:cpp-xsl, fp:rtm-cmakelists(., $fp:rtm-version))"/>
      <xsl:for-each select="r:instance">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('conf/', @name, '.conf'), 'generated', $fp:deploy-xsl, fp:instance-conf(.))"/>
      </xsl:for-each>
      <xsl:for-each select="r:process">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/', @file, '.rtc.conf'), 'generated', $fp:deploy-xsl, fp:rtc-conf($system, .))"/>
      </xsl:for-each>
      <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/', @deploy-name, '.rtsys.xml'), 'generated', $fp:profile-xsl, fp:rts-profile(., $fp:rtm-version))"/>
      <xsl:for-each-group select="r:process" group-by="string(@host-name)">
        <xsl:sequence select="$fp:file-margin, fp:file(concat('deploy/start_', replace(lower-case(current-grouping-key()), '[^a-z0-9_]', '_'), '.sh'), 'generated', $fp:deploy-xsl,
                                      fp:rtm-start-script($system, current-group()))"/>
      </xsl:for-each-group>
      <xsl:text>&#10;</xsl:text>
    </fs:files>
  </xsl:template>
</xsl:stylesheet>
